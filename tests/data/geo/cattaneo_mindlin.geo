// Two identical cylinders of radius R touching at the origin (Cattaneo–Mindlin, full models in x): the
// upper body is the half of the disc of centre (0, R) below y = R, the lower one the half of the disc of
// centre (0, -R) above y = -R. The contact arcs are meshed uniformly (transfinite, by angle): the upper at
// h, the lower at h / lower_scale (lower_scale = 1: matching interface nodes, the mirror images of each
// other; otherwise non-matching); the interiors are graded from h within d_min of the contact point to H
// beyond d_max. Without x_fine the whole quarter arcs are uniform; with it only the arcs |x| < x_fine, the
// rest of each arc graded by the same field as the interior.
// Set h (default 0.008), lower_scale (1), d_min, d_max (0.2, 0.6) and x_fine (none) from a wrapper file.
R = 1.0;
If (!Exists(h))
  h = 0.008;
EndIf
H = 0.1;
If (!Exists(d_min))
  d_min = 0.2;
EndIf
If (!Exists(d_max))
  d_max = 0.6;
EndIf
If (!Exists(x_fine))
  theta = 0.5 * Pi;
Else
  theta = Asin(x_fine / R);
EndIf
n = Ceil(theta * R / h) + 1;
If (!Exists(lower_scale))
  lower_scale = 1;
EndIf
n_lower = Ceil(lower_scale * theta * R / h) + 1;
s = R * Sin(theta);
t = R - R * Cos(theta);
Point(1) = {0, R, 0, H};
Point(2) = {-R, R, 0, H};
Point(3) = {0, 0, 0, h};
Point(4) = {R, R, 0, H};
Point(11) = {0, -R, 0, H};
Point(12) = {-R, -R, 0, H};
Point(13) = {0, 0, 0, h};
Point(14) = {R, -R, 0, H};
If (!Exists(x_fine))
  Circle(1) = {2, 1, 3};
  Circle(2) = {3, 1, 4};
  Line(3) = {4, 2};
  Curve Loop(1) = {1, 2, 3};
  Circle(11) = {12, 11, 13};
  Circle(12) = {13, 11, 14};
  Line(13) = {14, 12};
  Curve Loop(11) = {11, 12, 13};
  upper_arcs[] = {1, 2};
  lower_arcs[] = {11, 12};
  upper_fine[] = {1, 2};
  lower_fine[] = {11, 12};
Else
  Point(5) = {-s, t, 0, h};
  Point(6) = {s, t, 0, h};
  Point(15) = {-s, -t, 0, h};
  Point(16) = {s, -t, 0, h};
  Circle(1) = {2, 1, 5};
  Circle(2) = {5, 1, 3};
  Circle(4) = {3, 1, 6};
  Circle(5) = {6, 1, 4};
  Line(3) = {4, 2};
  Curve Loop(1) = {1, 2, 4, 5, 3};
  Circle(11) = {12, 11, 15};
  Circle(12) = {15, 11, 13};
  Circle(14) = {13, 11, 16};
  Circle(15) = {16, 11, 14};
  Line(13) = {14, 12};
  Curve Loop(11) = {11, 12, 14, 15, 13};
  upper_arcs[] = {1, 2, 4, 5};
  lower_arcs[] = {11, 12, 14, 15};
  upper_fine[] = {2, 4};
  lower_fine[] = {12, 14};
EndIf
Plane Surface(1) = {1};
Plane Surface(11) = {11};
Transfinite Curve{upper_fine[]} = n;
Transfinite Curve{lower_fine[]} = n_lower;
Field[1] = Distance;
Field[1].PointsList = {3, 13};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h;
Field[2].SizeMax = H;
Field[2].DistMin = d_min;
Field[2].DistMax = d_max;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Physical Surface("upper") = {1};
Physical Curve("upper_contact") = upper_arcs[];
Physical Curve("upper_top") = {3};
Physical Surface("lower") = {11};
Physical Curve("lower_contact") = lower_arcs[];
Physical Curve("lower_base") = {13};
