// Two unit cubes meshed with hexahedra: the foundation "lower" [0, 1]³ in 3 × 3 × 3 cells and the block
// "upper" [0, 1]² × [1, 2] in 4 × 4 × 4 (transfinite, recombined), so the two faces of the interface z = 1
// do not match. The boxes are not fused: each is meshed on its own. At order 2 Gmsh makes 27-node
// hexahedra (add Mesh.SecondOrderIncomplete = 1; for 20-node ones).
SetFactory("OpenCASCADE");
e = 1e-6;
Box(1) = {0, 0, 0, 1, 1, 1};
Box(2) = {0, 0, 1, 1, 1, 1};
Transfinite Curve{1:12} = 4;
Transfinite Surface{1:6};
Recombine Surface{1:6};
Transfinite Volume{1};
Recombine Volume{1};
Transfinite Curve{13:24} = 5;
Transfinite Surface{7:12};
Recombine Surface{7:12};
Transfinite Volume{2};
Recombine Volume{2};
Physical Volume("lower") = {1};
Physical Volume("upper") = {2};
Physical Surface("bottom") = {5};
Physical Surface("lower_top") = {6};
Physical Surface("upper_bottom") = {11};
Physical Surface("top") = {12};
// Corner points, by bounding box: each also catches the coincident corner of the other cube, which a
// body's restriction of the group leaves out.
Physical Point("origin") = Point In BoundingBox{-e, -e, -e, e, e, e};
Physical Point("lower_x") = Point In BoundingBox{1 - e, -e, -e, 1 + e, e, e};
Physical Point("upper_corner") = Point In BoundingBox{-e, -e, 2 - e, e, e, 2 + e};
Physical Point("upper_x") = Point In BoundingBox{1 - e, -e, 2 - e, 1 + e, e, 2 + e};
