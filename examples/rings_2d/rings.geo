// Concentric rings (VALIDATION.md, V6), quarter model: inner ring r in [0.5, 1], outer ring
// r in [1.001, 2], initial radial gap 0.001. Structured: nc elements along each quarter circle, nr
// across each ring.
If (!Exists(nc))
  nc = 32;
EndIf
If (!Exists(nr))
  nr = 8;
EndIf
r1 = 0.5; r2 = 1.0; r3 = 1.001; r4 = 2.0;
Point(1) = {0, 0, 0};
Point(2) = {r1, 0, 0}; Point(3) = {r2, 0, 0}; Point(4) = {0, r2, 0}; Point(5) = {0, r1, 0};
Point(6) = {r3, 0, 0}; Point(7) = {r4, 0, 0}; Point(8) = {0, r4, 0}; Point(9) = {0, r3, 0};
Line(1) = {2, 3}; Circle(2) = {3, 1, 4}; Line(3) = {4, 5}; Circle(4) = {5, 1, 2};
Line(5) = {6, 7}; Circle(6) = {7, 1, 8}; Line(7) = {8, 9}; Circle(8) = {9, 1, 6};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
Transfinite Curve{2, 4, 6, 8} = nc + 1;
Transfinite Curve{1, 3, 5, 7} = nr + 1;
Transfinite Surface{1}; Transfinite Surface{2};
Physical Surface("inner") = {1};
Physical Curve("inner_bottom") = {1};   // y = 0
Physical Curve("inner_left") = {3};     // x = 0
Physical Curve("inner_bore") = {4};     // r = 0.5, internal pressure
Physical Curve("inner_outside") = {2};  // r = 1, contact
Physical Surface("outer") = {2};
Physical Curve("outer_bottom") = {5};
Physical Curve("outer_left") = {7};
Physical Curve("outer_clamp") = {6};    // r = 2, clamped
Physical Curve("outer_inside") = {8};   // r = 1.001, contact
