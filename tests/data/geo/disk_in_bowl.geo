// A disk of radius 0.2 resting 0.001 above the bottom of a bowl: a block whose top is a concave arc of
// radius 2 (centre (0, 2), lowest point (0, 0)). Sliding the disk sideways by d along the bowl's bottom
// tangent puts it d²/(2 × 2) into the rising bowl: what small-sliding contact (frozen at the reference
// configuration) cannot see.
h = 0.04;
Point(1) = {-1.2, -0.5, 0, h}; Point(2) = {1.2, -0.5, 0, h};
Point(3) = {1.2, 0.4, 0, h}; Point(4) = {-1.2, 0.4, 0, h};  // 2 − sqrt(4 − 1.2²) = 0.4
Point(5) = {0, 2, 0, h}; Point(6) = {0, 0, 0, h};
Line(1) = {1, 2}; Line(2) = {2, 3}; Circle(3) = {3, 5, 6}; Circle(4) = {6, 5, 4}; Line(5) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4, 5}; Plane Surface(1) = {1};
Point(11) = {0, 0.201, 0, h / 2}; Point(12) = {0.2, 0.201, 0, h / 2}; Point(13) = {0, 0.401, 0, h / 2};
Point(14) = {-0.2, 0.201, 0, h / 2}; Point(15) = {0, 0.001, 0, h / 2};
Circle(6) = {12, 11, 13}; Circle(7) = {13, 11, 14}; Circle(8) = {14, 11, 15}; Circle(9) = {15, 11, 12};
Curve Loop(2) = {6, 7, 8, 9}; Plane Surface(2) = {2};
Physical Surface("bowl") = {1};
Physical Curve("bowl_bottom") = {1};
Physical Curve("bowl_top") = {3, 4};
Physical Surface("disk") = {2};
Physical Curve("disk_top") = {6, 7};
Physical Curve("disk_bottom") = {8, 9};
