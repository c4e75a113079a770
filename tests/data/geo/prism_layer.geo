// A unit cube in one body of two cell types: a layer of prisms (the triangulated square z = 0 extruded
// by 0.25 in two layers) under tetrahedra (its top extruded by 0.75, meshed unstructured), conforming on
// the triangles of z = 0.25: a boundary-layer mesh. The sides are a group per cell type (quadrilateral
// facets of the prisms, triangles of the tetrahedra); "sides" holds both.
lc = 0.35;
Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {1, 1, 0, lc}; Point(4) = {0, 1, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
layer[] = Extrude {0, 0, 0.25} { Surface{1}; Layers{2}; Recombine; };
core[] = Extrude {0, 0, 0.75} { Surface{layer[0]}; };
Physical Volume("block") = {layer[1], core[1]};
Physical Surface("zmin") = {1};
Physical Surface("zmax") = {core[0]};
Physical Surface("sides_prisms") = {layer[2], layer[3], layer[4], layer[5]};
Physical Surface("sides_tets") = {core[2], core[3], core[4], core[5]};
Physical Surface("sides") = {layer[2], layer[3], layer[4], layer[5], core[2], core[3], core[4], core[5]};
