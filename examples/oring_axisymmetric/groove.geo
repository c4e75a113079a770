// The rigid groove of oring.geo (mm): walls at r = 8.6 and 11.4, 1.6 high, bottom z = 0. Traversed with
// the housing on the left of each segment, so that the normals point into the groove.
Point(1) = {11.4, 1.6, 0, 0.1};
Point(2) = {11.4, 0, 0, 0.1};
Point(3) = {8.6, 0, 0, 0.1};
Point(4) = {8.6, 1.6, 0, 0.1};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Physical Curve("groove") = {1, 2, 3};
