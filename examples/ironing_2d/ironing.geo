// 2D ironing (Yang, Laursen and Meng, IJNME 2005, §6.3): a Neo-Hookean slab 9 × 3 (bottom fixed) and a
// stiff half-ring die, radii 2.8–3.0, centre (−2.7, 3.03), pressed down 1.4 and slid 4 along the slab.
// The slab is [−4.5, 4.5] × [−3, 0] (centred on x = 0, top at y = 0), so that the die's lowest point
// starts 0.03 above the top, at x = −2.7, and ends over x = 1.3. Element sizes: hs on the slab (finer near its top), hd on the die.
// Optional (set before including this file; both off by default, which gives the sharp corner the
// benchmark specifies, used by ironing.toml and ironing_mu0.3.toml):
//   rc: radius of a fillet rounding the slab's top-left corner (0: sharp), a variant of the geometry. The
//       die overhangs that corner and friction drags it under the die (ironing_mu0.3.toml).
//   hc: element size at that corner (within 0.2 + rc of the corner, or of the fillet's centre, growing
//       linearly to hs at 1.5 + rc); 0: hs everywhere on the slab's top.
If (!Exists(hs))
  hs = 0.15;
EndIf
If (!Exists(hd))
  hd = 0.1;
EndIf
If (!Exists(rc))
  rc = 0;
EndIf
If (!Exists(hc))
  hc = 0;
EndIf
xc = -2.7; yc = 3.03; ri = 2.8; ro = 3.0;

// Slab.
Point(1) = {-4.5, -3, 0, 2 * hs};
Point(2) = {4.5, -3, 0, 2 * hs};
Point(3) = {4.5, 0, 0, hs};
Line(1) = {1, 2};
Line(2) = {2, 3};
If (rc > 0)
  // Top-left corner rounded: the top ends at (−4.5 + rc, 0), a quarter circle (centre (−4.5 + rc, −rc))
  // leads to the left side at (−4.5, −rc).
  Point(4) = {-4.5 + rc, 0, 0, hs};
  Point(5) = {-4.5, -rc, 0, hs};
  Point(6) = {-4.5 + rc, -rc, 0, hs};
  Line(3) = {3, 4};
  Circle(5) = {4, 6, 5};
  Line(4) = {5, 1};
  Curve Loop(1) = {1, 2, 3, 5, 4};
  corner[] = {5};
Else
  Point(4) = {-4.5, 0, 0, hs};
  Line(3) = {3, 4};
  Line(4) = {4, 1};
  Curve Loop(1) = {1, 2, 3, 4};
  corner[] = {};
EndIf
Plane Surface(1) = {1};
If (hc > 0)
  // Size hc within 0.2 + rc of the corner (of the fillet's centre when rounded), growing linearly to hs at
  // 1.5 + rc; the point sizes beyond (StopAtDistMax).
  Field[1] = Distance;
  Field[1].PointsList = {(rc > 0 ? 6 : 4)};
  Field[2] = Threshold;
  Field[2].InField = 1;
  Field[2].SizeMin = hc;
  Field[2].SizeMax = hs;
  Field[2].StopAtDistMax = 1;
  Field[2].DistMin = 0.2 + rc;
  Field[2].DistMax = 1.5 + rc;
  Background Field = 2;
EndIf

// Die: the lower half of the ring, its two flat ends at y = yc.
Point(10) = {xc, yc, 0, hd};
Point(11) = {xc - ro, yc, 0, hd};
Point(12) = {xc, yc - ro, 0, hd};
Point(13) = {xc + ro, yc, 0, hd};
Point(14) = {xc + ri, yc, 0, hd};
Point(15) = {xc, yc - ri, 0, hd};
Point(16) = {xc - ri, yc, 0, hd};
Circle(10) = {11, 10, 12};
Circle(11) = {12, 10, 13};
Line(12) = {13, 14};
Circle(13) = {14, 10, 15};
Circle(14) = {15, 10, 16};
Line(15) = {16, 11};
Curve Loop(2) = {10, 11, 12, 13, 14, 15};
Plane Surface(2) = {2};

Physical Surface("slab") = {1};
Physical Curve("slab_bottom") = {1};
Physical Curve("slab_top") = {3};
// The top and both sides: with friction the die drags the slab's top-left corner under itself and its
// trailing side comes down on the slab's left side (ironing_mu0.3.toml).
Physical Curve("slab_contact") = {2, 3, corner[], 4};
Physical Surface("die") = {2};
Physical Curve("die_outer") = {10, 11};
Physical Curve("die_ends") = {12, 15};
