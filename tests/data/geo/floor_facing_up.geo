// The floor of floor_facing_away.geo traversed in -x: the facet normal (0, 1) points up, towards the square.
Point(1) = {-1, -0.05, 0, 0.5}; Point(2) = {2, -0.05, 0, 0.5};
Line(1) = {2, 1};
Physical Curve("floor") = {1};
