// Hertz 3D (VALIDATION.md, V2) with two identical elastic spheres R = 1 touching at the origin, quarter
// model: the sphere of sphere_on_plane.geo (centre (0, 0, 1)) and its mirror image in z = 0 (centre
// (0, 0, −1)). R_eff = 1/2 and E* = E / (2 (1 − ν²)) give the same a and p0 as one sphere on a rigid plane.
Include "sphere_on_plane.geo";
v[] = Symmetry {0, 0, 1, 0} { Duplicata { Volume{1}; } };
s[] = Boundary { Volume{v[0]}; };
Physical Volume("lower") = {v[0]};
Physical Surface("lower_contact") = {s[0]};
Physical Surface("lower_cut") = {s[1]};
Physical Surface("lower_symmetry_y") = {s[2]};
Physical Surface("lower_symmetry_x") = {s[3]};
// The refinement field measures the distance to the contact point, shared by both spheres.
