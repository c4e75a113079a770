#pragma once
/// \file contact_patch_case.hpp
/// Test helper: the 2D contact patch test of VALIDATION.md (V3), shared by the frictionless and the
/// frictional variants (tests/validation/test_contact_patch*.cpp).
///
/// Two unit blocks pressed together through a non-matching (or matching) interface: lower [0,1]×[0,1],
/// upper [0,1]×[1,2], n1 and n2 divisions per side (structured triangles, blocks.geo); E = 1, ν = 0.3,
/// plane strain; bottom u_y = 0, u_x = 0 at (0, 0); u_x = 0 at (0, 2) removes the upper block's free
/// sliding; pressure p = 0.01 on top. Exact: σ_yy = −p, contact pressure p, u_y = −(1 − ν²) p y / E,
/// u_x = ν (1 + ν) p x / E. Identical materials: no relative slip, so the answer is exact with friction too.
///
/// dim = 3: two cubes, lower [0,1]³ and upper [0,1]²×[1,2], unstructured tetrahedra of size 1/n1 and 1/n2
/// (Gmsh, so the interface meshes do not match); bottom u_z = 0; u_x = u_y = 0 at (0, 0, 0) and
/// (0, 0, 2), u_y = 0 at (1, 0, 0) and (1, 0, 2) (rigid motions only, the Poisson expansion is free).
/// Exact: σ_zz = −p, contact pressure p, u_z = −p z / E, u_x = ν p x / E, u_y = ν p y / E.

#include <string>

namespace symcontact::testing {

struct ContactPatchCase {
  int dim = 2;                     ///< 2: two blocks; 3: two cubes
  int n1 = 4, n2 = 5;              ///< divisions per side of the lower and the upper block
  int order = 1;                   ///< Lagrange order
  std::string mode = "symmetric";  ///< "symmetric" or "one-pass" (slave: surface b, the upper block's bottom unless swapped)
  bool swap = false;               ///< declare the upper body first
  double mu = -1.0;                ///< < 0: frictionless; ≥ 0: Coulomb friction with this coefficient
  double alpha = 0.0;              ///< friction regularisation length; 0: automatic
};

struct ContactPatchErrors {
  double displacement = 0.0;   ///< max nodal |u − u_exact| / max |u_exact|
  double pressure = 0.0;       ///< max over the contact nodes of both sides of |p − p_exact| / p_exact
  double tangential = 0.0;     ///< max |tangential traction| / p_exact over the contact nodes
  int geometry_iterations = 0, ipopt_iterations = 0, coulomb_iterations = 0;
};

/// The Gmsh file of the two blocks (physical groups: surfaces "lower", "upper"; curves "bottom",
/// "lower_top", "upper_bottom", "top"; points "origin", "upper_corner"). In 3D: volumes "lower", "upper";
/// surfaces "bottom", "lower_top", "upper_bottom", "top"; points "origin", "lower_x" (1, 0, 0),
/// "upper_corner" (0, 0, 2), "upper_x" (1, 0, 2).
std::string contact_patch_geo(int n1, int n2, int dim = 2);

/// The problem file (mesh "blocks.geo" in the same folder).
std::string contact_patch_toml(const ContactPatchCase& c);

/// Writes both files into a temporary folder, solves, and measures the errors against the exact solution.
ContactPatchErrors contact_patch_errors(const ContactPatchCase& c);

/// "n4_5_P1_symmetric" (+ "_swapped", "_mu0.3"; "3D_" first in 3D): a GoogleTest parameter name.
std::string contact_patch_name(const ContactPatchCase& c);

}  // namespace symcontact::testing
