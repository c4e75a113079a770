// An O-ring in a face-seal groove, axisymmetric section (r = x, z = y; mm). The ring's cross-section is a
// circle of diameter d = 2 centred at r = R0 = 10, z = 1, resting on the groove bottom z = 0; the lid, a
// steel plate 0.5 thick, starts on the ring's top z = 2. The groove (groove.geo, rigid) is 1.6 deep, so
// the lid brought down onto the housing squeezes the ring by 20 %, and 2.8 wide.
// h: the ring's element size (the default 0.15 puts 42 facets around the ring).
R0 = 10;
rho = 1;
If (!Exists(h))
  h = 0.15;
EndIf
Point(1) = {R0, rho, 0, h};          // centre of the cross-section
Point(2) = {R0 + rho, rho, 0, h};
Point(3) = {R0, 2 * rho, 0, h};
Point(4) = {R0 - rho, rho, 0, h};
Point(5) = {R0, 0, 0, h};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Surface("ring") = {1};
Physical Curve("ring_surface") = {1, 2, 3, 4};

// The lid: r in [R0 - 2, R0 + 2], z in [2, 2.5].
Point(11) = {R0 - 2, 2 * rho, 0, 4 * h};
Point(12) = {R0 + 2, 2 * rho, 0, 4 * h};
Point(13) = {R0 + 2, 2 * rho + 0.5, 0, 4 * h};
Point(14) = {R0 - 2, 2 * rho + 0.5, 0, 4 * h};
Line(11) = {11, 12};
Line(12) = {12, 13};
Line(13) = {13, 14};
Line(14) = {14, 11};
Curve Loop(11) = {11, 12, 13, 14};
Plane Surface(11) = {11};
Physical Surface("lid") = {11};
Physical Curve("lid_bottom") = {11};
Physical Curve("lid_top") = {13};
