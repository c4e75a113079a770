z0 = 0; t = 0.2; rh = 0.1; rw = 0.2;
Point(1) = {0, 0, z0};
For k In {0:1}
  r = (k == 0) ? rh : rw;
  Point(2 + 4*k) = {r, 0, z0}; Point(3 + 4*k) = {0, r, z0}; Point(4 + 4*k) = {-r, 0, z0}; Point(5 + 4*k) = {0, -r, z0};
  Circle(1 + 4*k) = {2 + 4*k, 1, 3 + 4*k}; Circle(2 + 4*k) = {3 + 4*k, 1, 4 + 4*k};
  Circle(3 + 4*k) = {4 + 4*k, 1, 5 + 4*k}; Circle(4 + 4*k) = {5 + 4*k, 1, 2 + 4*k};
EndFor
Point(10) = {-0.5, -0.5, z0}; Point(11) = {0.5, -0.5, z0}; Point(12) = {0.5, 0.5, z0}; Point(13) = {-0.5, 0.5, z0};
Line(9) = {10, 11}; Line(10) = {11, 12}; Line(11) = {12, 13}; Line(12) = {13, 10};
Curve Loop(1) = {1, 2, 3, 4}; Curve Loop(2) = {5, 6, 7, 8}; Curve Loop(3) = {9, 10, 11, 12};
Plane Surface(1) = {2, 1};
Plane Surface(2) = {3, 2};
e[] = Extrude {0, 0, t} { Surface{1, 2}; };
Coherence;
Physical Volume("solid") = {e[1], e[11]};
Physical Surface("bottom") = {1, 2};
Physical Surface("top") = {e[0], e[10]};
Physical Surface("washer_bottom") = {1};
Physical Surface("washer_top") = {e[0]};
