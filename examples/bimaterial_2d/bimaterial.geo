// A bar 2 x 0.2 of two halves bonded along x = 1: "steel" (0 <= x <= 1) and "rubber" (1 <= x <= 2),
// one body ("bar") meshed as one, so the interface nodes are shared. h: element size (a mesh parameter).
DefineConstant[ h = 0.2 ];
Point(1) = {0, 0, 0, h};
Point(2) = {1, 0, 0, h};
Point(3) = {2, 0, 0, h};
Point(4) = {2, 0.2, 0, h};
Point(5) = {1, 0.2, 0, h};
Point(6) = {0, 0.2, 0, h};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 6};
Line(6) = {6, 1};
Line(7) = {2, 5};  // the interface
Curve Loop(1) = {1, 7, 5, 6};
Plane Surface(1) = {1};
Curve Loop(2) = {2, 3, 4, -7};
Plane Surface(2) = {2};
Physical Surface("steel") = {1};
Physical Surface("rubber") = {2};
Physical Surface("bar") = {1, 2};
Physical Curve("left") = {6};
Physical Curve("right") = {3};
Physical Curve("bottom") = {1, 2};
