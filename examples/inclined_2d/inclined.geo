// Sliding on an inclined interface (VALIDATION.md, V5; the talk's second validation).
// The unit square [0,1]x[0,1] cut by the line through (0.5, 0.5) of slope tan(alpha) = 0.1, i.e.
// y = 0.45 + 0.1 x, into a lower and an upper body. Each body has its own points and curves, so the two
// meshes share no node; they are meshed at different sizes (h below, 0.75 h above), so the interface
// is non-matching.
//   lower: (0,0) (1,0) (1,0.55) (0,0.45)   groups: surface "lower"; curves "lower_bottom",
//          "lower_interface", "lower_left", "lower_right"
//   upper: (0,0.45) (1,0.55) (1,1) (0,1)    groups: surface "upper"; curves "upper_interface",
//          "upper_top", "upper_left", "upper_right"
// h, the element size of the lower body, can be set from outside (a wrapper file
// "h = 0.02; Include "inclined.geo";", as the tests and symcontact-bench do), or replaced by a smaller
// problem.mesh_size (the largest element size).
If (!Exists(h))
  h = 0.05;
EndIf
slope = 0.1;
y0 = 0.5 - 0.5 * slope;  // the interface at x = 0
y1 = 0.5 + 0.5 * slope;  // the interface at x = 1
hu = 0.75 * h;           // upper body: finer, so the meshes do not match

// Lower body.
Point(1) = {0, 0, 0, h};
Point(2) = {1, 0, 0, h};
Point(3) = {1, y1, 0, h};
Point(4) = {0, y0, 0, h};
Line(1) = {1, 2};   // bottom
Line(2) = {2, 3};   // right
Line(3) = {3, 4};   // interface, outward normal up
Line(4) = {4, 1};   // left
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

// Upper body (its own points: no node is shared with the lower body).
Point(11) = {0, y0, 0, hu};
Point(12) = {1, y1, 0, hu};
Point(13) = {1, 1, 0, hu};
Point(14) = {0, 1, 0, hu};
Line(11) = {11, 12};  // interface, outward normal down
Line(12) = {12, 13};  // right
Line(13) = {13, 14};  // top
Line(14) = {14, 11};  // left
Curve Loop(11) = {11, 12, 13, 14};
Plane Surface(11) = {11};

Physical Surface("lower") = {1};
Physical Curve("lower_bottom") = {1};
Physical Curve("lower_right") = {2};
Physical Curve("lower_interface") = {3};
Physical Curve("lower_left") = {4};
Physical Surface("upper") = {11};
Physical Curve("upper_interface") = {11};
Physical Curve("upper_right") = {12};
Physical Curve("upper_top") = {13};
Physical Curve("upper_left") = {14};
