// The two cubes of prism_blocks.geo extruded along x instead: each a triangulated square of the (y, z)
// plane (sizes 0.4 and 0.3) extruded in 3 and 4 layers, so that the faces z = 0, 1, 2 are made of the
// prisms' quadrilateral sides, and the two faces of the interface z = 1 do not match.
SetFactory("OpenCASCADE");  // keeps the two cubes apart: each is meshed on its own
e = 1e-6;
Point(1) = {0, 0, 0, 0.4}; Point(2) = {0, 1, 0, 0.4}; Point(3) = {0, 1, 1, 0.4}; Point(4) = {0, 0, 1, 0.4};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
// Extrude lists the copy of the surface, the volume, then the sides swept by lines 1, 2, 3, 4:
// z = 0, y = 1, z = 1, y = 0.
lower[] = Extrude {1, 0, 0} { Surface{1}; Layers{3}; Recombine; };
Point(101) = {0, 0, 1, 0.3}; Point(102) = {0, 1, 1, 0.3}; Point(103) = {0, 1, 2, 0.3};
Point(104) = {0, 0, 2, 0.3};
Line(101) = {101, 102}; Line(102) = {102, 103}; Line(103) = {103, 104}; Line(104) = {104, 101};
Curve Loop(101) = {101, 102, 103, 104}; Plane Surface(101) = {101};
upper[] = Extrude {1, 0, 0} { Surface{101}; Layers{4}; Recombine; };
Physical Volume("lower") = {lower[1]};
Physical Volume("upper") = {upper[1]};
Physical Surface("bottom") = {lower[2]};
Physical Surface("lower_top") = {lower[4]};
Physical Surface("upper_bottom") = {upper[2]};
Physical Surface("top") = {upper[4]};
Physical Point("origin") = Point In BoundingBox{-e, -e, -e, e, e, e};
Physical Point("lower_x") = Point In BoundingBox{1 - e, -e, -e, 1 + e, e, e};
Physical Point("upper_corner") = Point In BoundingBox{-e, -e, 2 - e, e, e, 2 + e};
Physical Point("upper_x") = Point In BoundingBox{1 - e, -e, 2 - e, 1 + e, e, 2 + e};
