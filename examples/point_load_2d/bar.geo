// A 10 x 1 bar: left edge on rollers (ux = 0), its bottom-left corner pinned (uy = 0), pulled by a point
// force at the middle of its right edge. "mid" is a mesh node at mid-length on the axis.
L = 10;
H = 1;
lc = 0.1;
Point(1) = {0, 0, 0, lc};
Point(2) = {L, 0, 0, lc};
Point(3) = {L, H / 2, 0, lc / 4};
Point(4) = {L, H, 0, lc};
Point(5) = {0, H, 0, lc};
Point(6) = {L / 2, H / 2, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 1};
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};
Point{6} In Surface{1};
Physical Surface("bar") = {1};
Physical Curve("left") = {5};
Physical Curve("right") = {2, 3};
Physical Point("origin") = {1};
Physical Point("tip") = {3};
Physical Point("mid") = {6};
