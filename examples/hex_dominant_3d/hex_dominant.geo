// Two unit cubes, each a hex-dominant mesh: hexahedra at the contact interface z = 1, tetrahedra away from
// it, and the pyramids Gmsh builds on the hexahedra's faces where the tetrahedra meet them. The foundation
// "lower" [0, 1]³: the square z = 0.5 cut into 3 × 3 quadrilaterals, extruded up to z = 1 in two layers of
// hexahedra and down to z = 0 as an unstructured volume. The block "upper" [0, 1]² × [1, 2]: the square
// z = 1.5 cut into 4 × 4, extruded down to z = 1 in hexahedra and up to z = 2 unstructured. The two
// quadrilateral faces of the interface do not match.
SetFactory("OpenCASCADE");  // keeps the two cubes apart: each is meshed on its own
e = 1e-6;
lc = 0.3;
Point(1) = {0, 0, 0.5, lc}; Point(2) = {1, 0, 0.5, lc}; Point(3) = {1, 1, 0.5, lc}; Point(4) = {0, 1, 0.5, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = 4;
Transfinite Surface{1};
Recombine Surface{1};
lower_hex[] = Extrude {0, 0, 0.5} { Surface{1}; Layers{2}; Recombine; };
lower_tet[] = Extrude {0, 0, -0.5} { Surface{1}; };
Point(101) = {0, 0, 1.5, lc}; Point(102) = {1, 0, 1.5, lc}; Point(103) = {1, 1, 1.5, lc};
Point(104) = {0, 1, 1.5, lc};
Line(101) = {101, 102}; Line(102) = {102, 103}; Line(103) = {103, 104}; Line(104) = {104, 101};
Curve Loop(101) = {101, 102, 103, 104}; Plane Surface(101) = {101};
Transfinite Curve{101, 102, 103, 104} = 5;
Transfinite Surface{101};
Recombine Surface{101};
upper_hex[] = Extrude {0, 0, -0.5} { Surface{101}; Layers{2}; Recombine; };
upper_tet[] = Extrude {0, 0, 0.5} { Surface{101}; };
Physical Volume("lower") = {lower_hex[1], lower_tet[1]};
Physical Volume("upper") = {upper_hex[1], upper_tet[1]};
Physical Surface("bottom") = {lower_tet[0]};
Physical Surface("lower_top") = {lower_hex[0]};
Physical Surface("upper_bottom") = {upper_hex[0]};
Physical Surface("top") = {upper_tet[0]};
// Corner points, by bounding box: each also catches the coincident corner of the other cube, which a
// body's restriction of the group leaves out.
Physical Point("origin") = Point In BoundingBox{-e, -e, -e, e, e, e};
Physical Point("lower_x") = Point In BoundingBox{1 - e, -e, -e, 1 + e, e, e};
Physical Point("upper_corner") = Point In BoundingBox{-e, -e, 2 - e, e, e, 2 + e};
Physical Point("upper_x") = Point In BoundingBox{1 - e, -e, 2 - e, 1 + e, e, 2 + e};
