// Two identical cylinders of radius R touching at the origin (Cattaneo–Mindlin, full models in x): the
// upper body is the half of the disc of centre (0, R) below y = R, the lower one the half of the disc of
// centre (0, -R) above y = -R. The contact arcs are meshed uniformly (transfinite, by angle): the upper with
// n nodes per quarter arc, the lower with n_lower (= n: matching interface nodes, the mirror images of each
// other; otherwise non-matching); the interiors are graded from h near the contact to H far from it.
// Set h (default 0.008) and n_lower (default: matching) from a wrapper file.
R = 1.0;
If (!Exists(h))
  h = 0.008;
EndIf
H = 0.1;
n = Ceil(0.5 * Pi * R / h) + 1;
If (!Exists(n_lower))
  n_lower = n;
EndIf
Point(1) = {0, R, 0, H};
Point(2) = {-R, R, 0, H};
Point(3) = {0, 0, 0, h};
Point(4) = {R, R, 0, H};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Line(3) = {4, 2};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Point(11) = {0, -R, 0, H};
Point(12) = {-R, -R, 0, H};
Point(13) = {0, 0, 0, h};
Point(14) = {R, -R, 0, H};
Circle(11) = {12, 11, 13};
Circle(12) = {13, 11, 14};
Line(13) = {14, 12};
Curve Loop(11) = {11, 12, 13};
Plane Surface(11) = {11};
Transfinite Curve{1, 2} = n;
Transfinite Curve{11, 12} = n_lower;
Field[1] = Distance;
Field[1].PointsList = {3, 13};
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
Physical Curve("upper_contact") = {1, 2};
Physical Curve("upper_top") = {3};
Physical Surface("lower") = {11};
Physical Curve("lower_contact") = {11, 12};
Physical Curve("lower_base") = {13};
