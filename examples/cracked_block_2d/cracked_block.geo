// A block [0, 1] x [0, 2] cracked right across at y = 1: its lower half [0, 1] x [0, 1] and its upper half
// [0, 1] x [1, 2] are meshed apart (4 and 5 divisions per side, so the crack's faces do not match) and form
// ONE body, "block". The crack's two faces are one boundary group, "crack", declared in self-contact in
// cracked_block.toml. The points at (0, 1) and (1, 1) are given twice (one per half) so that the halves
// keep their own nodes there.
Geometry.AutoCoherence = 0;
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Point(5) = {0, 1, 0}; Point(6) = {1, 1, 0}; Point(7) = {1, 2, 0}; Point(8) = {0, 2, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Transfinite Curve{1, 2, 3, 4} = 5;
Transfinite Curve{5, 6, 7, 8} = 6;
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1}; Transfinite Surface{1};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2}; Transfinite Surface{2};
Physical Surface("block") = {1, 2};
Physical Curve("bottom") = {1};
Physical Curve("top") = {7};
Physical Curve("crack") = {3, 5};
Physical Point("origin") = {1};
Physical Point("upper_corner") = {8};
