// A rigid floor y = -0.05 under the unit square of square.geo, its one line traversed in +x: the facet
// normal (t_y, -t_x) = (0, -1) points down, away from the square (a wrongly oriented obstacle).
Point(1) = {-1, -0.05, 0, 0.5}; Point(2) = {2, -0.05, 0, 0.5};
Line(1) = {1, 2};
Physical Curve("floor") = {1};
