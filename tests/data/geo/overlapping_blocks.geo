// Two unit squares overlapping by half their size: "lower" [0,1]×[0,1], "upper" [0,1]×[0.5,1.5], meshed
// separately (no shared nodes).
lc = 0.25;
Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {1, 1, 0, lc}; Point(4) = {0, 1, 0, lc};
Point(5) = {0, 0.5, 0, lc}; Point(6) = {1, 0.5, 0, lc}; Point(7) = {1, 1.5, 0, lc}; Point(8) = {0, 1.5, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
Physical Surface("lower") = {1};
Physical Surface("upper") = {2};
Physical Curve("lower_bottom") = {1};
Physical Curve("lower_top") = {3};
Physical Curve("upper_bottom") = {5};
Physical Curve("upper_top") = {7};
