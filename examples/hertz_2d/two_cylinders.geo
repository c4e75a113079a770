// Hertz 2D (VALIDATION.md, V1): two identical cylinders R = 1, half models (x >= 0) touching at the
// origin: the upper quarter disk below its centre (0, 1), the lower quarter disk above its centre
// (0, -1). Fine elements (size h) near the contact point.
R = 1.0;
If (!Exists(h))
  h = 0.004;
EndIf
H = 0.08;
// Upper cylinder.
Point(1) = {0, R, 0, H};
Point(2) = {0, 0, 0, h};
Point(3) = {R, R, 0, H};
Circle(1) = {2, 1, 3};
Line(2) = {3, 1};
Line(3) = {1, 2};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
// Lower cylinder (its own points: the bodies share no node).
Point(11) = {0, -R, 0, H};
Point(12) = {0, 0, 0, h};
Point(13) = {R, -R, 0, H};
Circle(11) = {13, 11, 12};
Line(12) = {11, 13};
Line(13) = {12, 11};
Curve Loop(11) = {11, 13, 12};
Plane Surface(11) = {11};
Field[1] = Distance;
Field[1].PointsList = {2, 12};
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
Physical Surface("upper") = {1};
Physical Curve("upper_contact") = {1};
Physical Curve("upper_load") = {2};
Physical Curve("upper_symmetry") = {3};
Physical Surface("lower") = {11};
Physical Curve("lower_contact") = {11};
Physical Curve("lower_base") = {12};
Physical Curve("lower_symmetry") = {13};
