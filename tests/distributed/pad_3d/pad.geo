// A pad [-1/2, 1/2]^2 x [0, 1/4], its bottom face on a rigid plane (pad.toml).
Point(1) = {-0.5, -0.5, 0}; Point(2) = {0.5, -0.5, 0}; Point(3) = {0.5, 0.5, 0}; Point(4) = {-0.5, 0.5, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
e[] = Extrude {0, 0, 0.25} { Surface{1}; };
Physical Volume("solid") = {e[1]};
Physical Surface("bottom") = {1};
Physical Surface("top") = {e[0]};
