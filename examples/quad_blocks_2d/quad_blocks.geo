// Two unit blocks meshed with quadrilaterals: the foundation "lower" [0, 1] x [0, 1], 4 x 4 structured
// (Transfinite, Recombine), and the block "upper" [0, 1] x [1, 2], unstructured (Blossom recombination of
// a triangulation of size 0.3), so the two faces of the interface y = 1 do not match. At order 2 Gmsh
// makes 9-node quadrilaterals (add Mesh.SecondOrderIncomplete = 1; for 8-node ones).
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Point(5) = {0, 1, 0, 0.3}; Point(6) = {1, 1, 0, 0.3}; Point(7) = {1, 2, 0, 0.3}; Point(8) = {0, 2, 0, 0.3};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Transfinite Curve{1, 2, 3, 4} = 5;
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1}; Transfinite Surface{1};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
Recombine Surface{1, 2};
Physical Surface("lower") = {1};
Physical Surface("upper") = {2};
Physical Curve("bottom") = {1};
Physical Curve("lower_top") = {3};
Physical Curve("upper_bottom") = {5};
Physical Curve("top") = {7};
Physical Point("origin") = {1};
Physical Point("upper_corner") = {8};
