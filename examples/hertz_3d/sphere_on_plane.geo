// Hertz 3D (VALIDATION.md, V2): quarter model of a sphere R = 1 resting on a rigid plane z = 0.
// The part x >= 0, y >= 0, z <= 1 of the ball centred at (0, 0, 1): its flat cut z = 1 carries the load,
// x = 0 and y = 0 are symmetry planes. Fine elements (size h) near the contact point (0, 0, 0).
R = 1.0;
If (!Exists(h))
  h = 0.02;
EndIf
H = 0.25;
Point(1) = {0, 0, R, H};   // centre
Point(2) = {0, 0, 0, h};   // contact point (south pole)
Point(3) = {R, 0, R, H};
Point(4) = {0, R, R, H};
Circle(1) = {2, 1, 3};     // meridian in y = 0
Circle(2) = {3, 1, 4};     // equator quarter in z = 1
Circle(3) = {4, 1, 2};     // meridian in x = 0
Line(4) = {1, 2};
Line(5) = {1, 3};
Line(6) = {1, 4};
Curve Loop(1) = {1, 2, 3};
Surface(1) = {1} In Sphere {1};   // spherical octant: the contact surface
Curve Loop(2) = {5, 2, -6};
Plane Surface(2) = {2};            // z = 1: load
Curve Loop(3) = {4, 1, -5};
Plane Surface(3) = {3};            // y = 0
Curve Loop(4) = {6, 3, -4};
Plane Surface(4) = {4};            // x = 0
Surface Loop(1) = {1, 2, 3, 4};
Volume(1) = {1};
// Refine near the contact point (the contact radius is a = 0.19).
Field[1] = Distance;
Field[1].PointsList = {2};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h;
Field[2].SizeMax = H;
Field[2].DistMin = 0.25;
Field[2].DistMax = 0.8;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Physical Volume("sphere") = {1};
Physical Surface("contact") = {1};
Physical Surface("load") = {2};
Physical Surface("symmetry_y") = {3};
Physical Surface("symmetry_x") = {4};
