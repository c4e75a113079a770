// A unit cube in one body of three cell types: hexahedra below (the square z = 0, transfinite and
// recombined, extruded by 0.5 in two layers) and tetrahedra above (its top extruded by 0.5, meshed
// unstructured), joined by the pyramids Gmsh builds on the hexahedra's top faces: a hex-dominant mesh.
// The sides are a group per facet type (quadrilaterals of the hexahedra, triangles above); "sides"
// holds both. `incomplete = 1` gives 13-node pyramids, 20-node hexahedra and 15-node prisms at order 2.
DefineConstant[ incomplete = 0 ];
Mesh.SecondOrderIncomplete = incomplete;
lc = 0.3;
Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {1, 1, 0, lc}; Point(4) = {0, 1, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Transfinite Curve{1, 2, 3, 4} = 4;
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Surface{1};
Recombine Surface{1};
layer[] = Extrude {0, 0, 0.5} { Surface{1}; Layers{2}; Recombine; };
core[] = Extrude {0, 0, 0.5} { Surface{layer[0]}; };
Physical Volume("block") = {layer[1], core[1]};
Physical Surface("zmin") = {1};
Physical Surface("zmax") = {core[0]};
Physical Surface("sides_hex") = {layer[2], layer[3], layer[4], layer[5]};
Physical Surface("sides_tets") = {core[2], core[3], core[4], core[5]};
Physical Surface("sides") = {layer[2], layer[3], layer[4], layer[5], core[2], core[3], core[4], core[5]};
