// Sliding on an inclined interface in 3D (VALIDATION.md, V5): the 2D case of examples/inclined_2d
// extruded in z by a slab of thickness w. The unit square cut by the line through (0.5, 0.5) of slope
// tan(alpha) = 0.1, y = 0.45 + 0.1 x, into a lower and an upper body, each extruded to 0 <= z <= w.
// Each body has its own points, curves and surfaces, so the meshes share no node; they are meshed with
// unstructured tetrahedra at different sizes (h below, 0.75 h above): the interface does not match.
//   lower: volume "lower"; surfaces "lower_bottom", "lower_interface", "lower_front" (z = 0),
//          "lower_back" (z = w)
//   upper: volume "upper"; surfaces "upper_interface", "upper_top", "upper_front", "upper_back"
// h can be set from outside (a wrapper file "h = 0.1; Include "inclined.geo";", as the test does).
If (!Exists(h))
  h = 0.1;
EndIf
If (!Exists(w))
  w = 0.2;
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
Line(3) = {3, 4};   // interface
Line(4) = {4, 1};   // left
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

// Upper body (its own points: no node is shared with the lower body).
Point(11) = {0, y0, 0, hu};
Point(12) = {1, y1, 0, hu};
Point(13) = {1, 1, 0, hu};
Point(14) = {0, 1, 0, hu};
Line(11) = {11, 12};  // interface
Line(12) = {12, 13};  // right
Line(13) = {13, 14};  // top
Line(14) = {14, 11};  // left
Curve Loop(11) = {11, 12, 13, 14};
Plane Surface(11) = {11};

// Extrusions: out[0] the face at z = w, out[1] the volume, out[2..5] the faces swept by the curves of
// the loop, in its order. No Layers: the volumes are meshed with tetrahedra (layers would give prisms).
lo[] = Extrude {0, 0, w} { Surface{1}; };
up[] = Extrude {0, 0, w} { Surface{11}; };

Physical Volume("lower") = {lo[1]};
Physical Surface("lower_bottom") = {lo[2]};
Physical Surface("lower_interface") = {lo[4]};
Physical Surface("lower_front") = {1};
Physical Surface("lower_back") = {lo[0]};
Physical Volume("upper") = {up[1]};
Physical Surface("upper_interface") = {up[2]};
Physical Surface("upper_top") = {up[4]};
Physical Surface("upper_front") = {11};
Physical Surface("upper_back") = {up[0]};
