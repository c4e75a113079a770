// Two unit blocks, each meshed with quadrilaterals and triangles together (one body, two element types):
// the foundation "lower" [0, 1] x [0, 1] with a structured, recombined left half (2 x 4 quadrilaterals)
// and a triangulated right half; the block "upper" [0, 1] x [1, 2] triangulated for x < 0.4 and
// recombined (unstructured) beyond. The interface y = 1 does not match, and each face of it runs along
// both types. At order 2 Gmsh makes 9-node quadrilaterals and 6-node triangles.
Point(1) = {0, 0, 0, 0.25}; Point(2) = {0.5, 0, 0, 0.25}; Point(3) = {1, 0, 0, 0.25};
Point(4) = {1, 1, 0, 0.25}; Point(5) = {0.5, 1, 0, 0.25}; Point(6) = {0, 1, 0, 0.25};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5}; Line(5) = {5, 6}; Line(6) = {6, 1};
Line(7) = {2, 5};
Transfinite Curve{1, 5} = 3; Transfinite Curve{6, 7} = 5;
Curve Loop(1) = {1, 7, 5, 6}; Plane Surface(1) = {1}; Transfinite Surface{1}; Recombine Surface{1};
Curve Loop(2) = {2, 3, 4, -7}; Plane Surface(2) = {2};

Point(7) = {0, 1, 0, 0.3}; Point(8) = {0.4, 1, 0, 0.3}; Point(9) = {1, 1, 0, 0.3};
Point(10) = {1, 2, 0, 0.3}; Point(11) = {0.4, 2, 0, 0.3}; Point(12) = {0, 2, 0, 0.3};
Line(8) = {7, 8}; Line(9) = {8, 9}; Line(10) = {9, 10}; Line(11) = {10, 11}; Line(12) = {11, 12};
Line(13) = {12, 7}; Line(14) = {8, 11};
Curve Loop(3) = {8, 14, 12, 13}; Plane Surface(3) = {3};
Curve Loop(4) = {9, 10, 11, -14}; Plane Surface(4) = {4}; Recombine Surface{4};

Physical Surface("lower") = {1, 2};
Physical Surface("upper") = {3, 4};
Physical Curve("bottom") = {1, 2};
Physical Curve("lower_top") = {4, 5};
Physical Curve("upper_bottom") = {8, 9};
Physical Curve("top") = {11, 12};
Physical Point("origin") = {1};
Physical Point("upper_corner") = {12};
