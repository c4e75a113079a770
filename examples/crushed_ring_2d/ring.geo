// A ring crushed between two plates (the self-contact showcase, issue #6): outer radius Ro, inner
// radius Ri, plane strain. The outer arcs within ±a of the top and bottom poles are the "plates"
// (prescribed displacement); the whole inner circle is the self-contact surface.
//
// Structured and mirror-symmetric node for node about x = 0 and y = 0, so that a symmetric solution
// can be checked to round-off: the ring is cut at the angles 0, 90 − a, 90, 90 + a, 180, ... into 8
// four-sided patches, each meshed transfinite (nl cells along the long arcs, ns along the plate arcs,
// nr across). A patch and its mirror image are traversed in opposite senses, so their cells are split
// by opposite diagonals ("Left" and "Right" below) — the mirror image of a Left split is a Right split.
//
// Groups: surface "ring"; curves "inner" (r = Ri, contact), "plate_top", "plate_bottom" (r = Ro,
// |angle − ±90°| ≤ a), "outer_free" (the rest of r = Ro).
// nl, ns and nr can be set by a wrapper file before Include (the test uses a coarser mesh).
If (!Exists(nl))
  nl = 28;
EndIf
If (!Exists(ns))
  ns = 8;
EndIf
If (!Exists(nr))
  nr = 4;
EndIf
Ro = 1.0; Ri = 0.8; a = 15 * Pi / 180;
Point(1) = {0, 0, 0};
th[] = {0, Pi / 2 - a, Pi / 2, Pi / 2 + a, Pi, 3 * Pi / 2 - a, 3 * Pi / 2, 3 * Pi / 2 + a};
For k In {0 : 7}
  Point(10 + k) = {Ri * Cos(th[k]), Ri * Sin(th[k]), 0};  // inner
  Point(20 + k) = {Ro * Cos(th[k]), Ro * Sin(th[k]), 0};  // outer
  Line(10 + k) = {10 + k, 20 + k};                        // radial cut at th[k]
EndFor
For k In {0 : 7}
  k1 = (k + 1) % 8;
  Circle(20 + k) = {10 + k, 1, 10 + k1};  // inner arc, counter-clockwise
  Circle(30 + k) = {20 + k, 1, 20 + k1};  // outer arc, counter-clockwise
  Curve Loop(40 + k) = {10 + k, 30 + k, -(10 + k1), -(20 + k)};
  Plane Surface(40 + k) = {40 + k};
  n = (k % 4 == 0 || k % 4 == 3) ? nl : ns;  // patches 0, 3, 4, 7 span the long arcs
  Transfinite Curve{20 + k, 30 + k} = n + 1;
EndFor
Transfinite Curve{10 : 17} = nr + 1;
For k In {0 : 7}
  k1 = (k + 1) % 8;
  If (k % 4 < 2)
    Transfinite Surface{40 + k} = {10 + k, 10 + k1, 20 + k1, 20 + k} Left;
  Else
    Transfinite Surface{40 + k} = {10 + k, 10 + k1, 20 + k1, 20 + k} Right;
  EndIf
EndFor
Physical Surface("ring") = {40 : 47};
Physical Curve("inner") = {20 : 27};
Physical Curve("plate_top") = {31, 32};
Physical Curve("plate_bottom") = {35, 36};
Physical Curve("outer_free") = {30, 33, 34, 37};
