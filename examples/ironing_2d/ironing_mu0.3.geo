// Mesh of ironing_mu0.3.toml: ironing.geo with the slab's top-left corner rounded (fillet radius rc)
// and refined there (element size hc). The die overhangs that corner and friction drags it under the die;
// with the sharp corner the slab's surface folds there into a crease and the solve stops at step 47
// (docs/validation.md, "Ironing"). The fillet is a modelling choice: the slab stays 9 × 3 otherwise.
rc = 0.2;
hc = 0.05;
Include "ironing.geo";
