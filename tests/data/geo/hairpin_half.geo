// V7 self-contact by symmetry (VALIDATION.md), 2D: the upper half of a hairpin (a C-shaped body) cut
// on its symmetry line y = 0. An arm of length L and thickness t joined to a back of width t; the arm's
// inner face carries a circular bump (radius R, height b, lowest point (xc, g/2)), so that the arms,
// pressed together, touch at the bumps, away from the ends of the surface. The back's cut (y = 0) is
// the symmetry boundary; the inner face is the contact surface; the top carries the load.
// The whole hairpin is this mesh and its mirror image (tests/support/mirrored_mesh).
If (!Exists(h))
  h = 0.05;
EndIf
L = 2.0; t = 0.3; g = 0.02; b = 0.05; R = 3.0; xc = 1.4;
yi = g / 2 + b;                  // the inner face away from the bump
c = Sqrt(R * R - (R - b) * (R - b));  // half-chord of the bump
hb = h / 5;                      // element size on the bump
Point(1) = {-t, 0, 0, h};
Point(2) = {0, 0, 0, h};
Point(3) = {0, yi, 0, h};
Point(4) = {xc - c, yi, 0, hb};
Point(5) = {xc, g / 2, 0, hb};
Point(6) = {xc + c, yi, 0, hb};
Point(7) = {L, yi, 0, h};
Point(8) = {L, yi + t, 0, h};
Point(9) = {-t, yi + t, 0, h};
Point(10) = {xc, g / 2 + R, 0, h};  // centre of the bump
Line(1) = {1, 2};        // symmetry cut
Line(2) = {2, 3};        // back, inner side
Line(3) = {3, 4};        // arm, inner face ...
Circle(4) = {4, 10, 5};  // ... the bump ...
Circle(5) = {5, 10, 6};
Line(6) = {6, 7};        // ... the rest of the inner face
Line(7) = {7, 8};        // arm end
Line(8) = {8, 9};        // top: load
Line(9) = {9, 1};        // back, outer side
Curve Loop(1) = {1, 2, 3, 4, 5, 6, 7, 8, 9};
Plane Surface(1) = {1};
Physical Surface("hairpin") = {1};
Physical Curve("symmetry") = {1};
Physical Curve("inner") = {3, 4, 5, 6};
Physical Curve("top") = {8};
Physical Curve("back") = {9};
