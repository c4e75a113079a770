// V7 self-contact by symmetry (VALIDATION.md), 3D: the upper half of a hairpin (a C-shaped body) of
// width W in z, cut on its symmetry plane y = 0. An arm of length L and thickness t joined to a back of
// width t; the arm's inner face carries a spherical bump (a cap of a sphere of radius R, height b, lowest
// point (xc, g/2, W/2)), so that the arms, pressed together, touch at the bumps, away from the borders of
// the contact surface. Groups: volume "hairpin"; surfaces "symmetry" (the back's cut, y = 0), "inner"
// (the arm's inner face and the bump), "top" (the load), "back" (x = −t). The whole hairpin is this mesh
// and its mirror image (tests/support/mirrored_mesh). h (element size), hb (on the bump), xc and W can be
// set by a wrapper file before Include.
SetFactory("OpenCASCADE");
If (!Exists(h))
  h = 0.15;
EndIf
L = 2.0; t = 0.3; g = 0.02; b = 0.05; R = 3.0;
If (!Exists(xc))
  xc = 1.4;
EndIf
If (!Exists(W))
  W = 1.4;
EndIf
yi = g / 2 + b;  // the inner face away from the bump
If (!Exists(hb))
  hb = h / 3;    // element size on the bump
EndIf
e = 1e-6;
Box(1) = {-t, 0, 0, t, yi + t, W};  // the back
Box(2) = {0, yi, 0, L, t, W};       // the arm
Sphere(3) = {xc, g / 2 + R, W / 2, R};
Box(4) = {xc - 1, g / 2 - e, W / 2 - 1, 2, b + e, 2};  // the slab of the cap, below the arm
BooleanIntersection(5) = {Volume{3}; Delete;}{Volume{4}; Delete;};
BooleanUnion(6) = {Volume{1}; Delete;}{Volume{2}; Volume{5}; Delete;};
MeshSize{PointsOf{Volume{6};}} = h;
// The bump: the only face strictly inside 0 < x < L below the arm (OpenCASCADE's bounding box of the
// spherical face is looser than the face, so the box is generous in y and z).
cap() = Surface In BoundingBox{0.01, -1, -1, L - 0.01, yi + t / 2, W + 1};
arm() = Surface In BoundingBox{-e, yi - e, -e, L + e, yi + e, W + e};  // the arm's flat inner face
MeshSize{PointsOf{Surface{cap()};}} = hb;
Physical Volume("hairpin") = {6};
Physical Surface("symmetry") = Surface In BoundingBox{-t - e, -e, -e, e, e, W + e};
Physical Surface("inner") = {arm(), cap()};
Physical Surface("top") = Surface In BoundingBox{-t - e, yi + t - e, -e, L + e, yi + t + e, W + e};
Physical Surface("back") = Surface In BoundingBox{-t - e, -e, -e, -t + e, yi + t + e, W + e};
