// Hertz 2D (VALIDATION.md, V1): half model of a cylinder R = 1 resting on a rigid plane y = 0.
// The quarter disk x >= 0, y <= 1 around the centre (0, 1); the flat cut y = 1 carries the load,
// x = 0 is the symmetry line. Fine elements (size h) near the contact point (0, 0).
R = 1.0;
If (!Exists(h))
  h = 0.004;
EndIf
H = 0.08;
Point(1) = {0, R, 0, H};       // centre
Point(2) = {0, 0, 0, h};       // contact point
Point(3) = {R, R, 0, H};
Circle(1) = {2, 1, 3};          // arc: contact surface
Line(2) = {3, 1};               // flat cut (load)
Line(3) = {1, 2};               // symmetry line
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
// Refine near the contact point.
Field[1] = Distance;
Field[1].PointsList = {2};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h;
Field[2].SizeMax = H;
Field[2].DistMin = 0.2;
Field[2].DistMax = 0.6;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Physical Surface("cylinder") = {1};
Physical Curve("contact") = {1};
Physical Curve("load") = {2};
Physical Curve("symmetry") = {3};
