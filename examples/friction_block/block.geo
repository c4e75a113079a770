// An elastic block W x H resting on a rigid plane y = 0 (VALIDATION.md, V4).
If (!Exists(n))
  n = 8;   // elements through the height
EndIf
W = 4; H = 1;
Point(1) = {0, 0, 0}; Point(2) = {W, 0, 0}; Point(3) = {W, H, 0}; Point(4) = {0, H, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Transfinite Curve{1, 3} = 4 * n + 1;
Transfinite Curve{2, 4} = n + 1;
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1}; Transfinite Surface{1};
Physical Surface("block") = {1};
Physical Curve("bottom") = {1};
Physical Curve("top") = {3};
Physical Curve("right") = {2};
Physical Curve("left") = {4};
