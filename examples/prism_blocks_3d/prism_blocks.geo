// Two unit cubes meshed with 6-node prisms: each a triangulated square extruded along z in layers
// (Extrude with Recombine), the foundation "lower" [0, 1]³ from triangles of size 0.4 in 3 layers, the
// block "upper" [0, 1]² × [1, 2] from triangles of size 0.3 in 4 layers, so the two triangulated faces of
// the interface z = 1 do not match. The sides of the cubes are the prisms' quadrilateral faces.
SetFactory("OpenCASCADE");  // keeps the two cubes apart: each is meshed on its own
e = 1e-6;
Point(1) = {0, 0, 0, 0.4}; Point(2) = {1, 0, 0, 0.4}; Point(3) = {1, 1, 0, 0.4}; Point(4) = {0, 1, 0, 0.4};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
lower[] = Extrude {0, 0, 1} { Surface{1}; Layers{3}; Recombine; };
Point(101) = {0, 0, 1, 0.3}; Point(102) = {1, 0, 1, 0.3}; Point(103) = {1, 1, 1, 0.3};
Point(104) = {0, 1, 1, 0.3};
Line(101) = {101, 102}; Line(102) = {102, 103}; Line(103) = {103, 104}; Line(104) = {104, 101};
Curve Loop(101) = {101, 102, 103, 104}; Plane Surface(101) = {101};
upper[] = Extrude {0, 0, 1} { Surface{101}; Layers{4}; Recombine; };
Physical Volume("lower") = {lower[1]};
Physical Volume("upper") = {upper[1]};
Physical Surface("bottom") = {1};
Physical Surface("lower_top") = {lower[0]};
Physical Surface("upper_bottom") = {101};
Physical Surface("top") = {upper[0]};
// Corner points, by bounding box: each also catches the coincident corner of the other cube, which a
// body's restriction of the group leaves out.
Physical Point("origin") = Point In BoundingBox{-e, -e, -e, e, e, e};
Physical Point("lower_x") = Point In BoundingBox{1 - e, -e, -e, 1 + e, e, e};
Physical Point("upper_corner") = Point In BoundingBox{-e, -e, 2 - e, e, e, 2 + e};
Physical Point("upper_x") = Point In BoundingBox{1 - e, -e, 2 - e, 1 + e, e, 2 + e};
