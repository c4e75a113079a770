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
///
/// n3 > 0: three blocks stacked, "lower" [0,1]×[0,1], "middle" [0,1]×[1,2], "upper" [0,1]×[2,3] (3D: ×[0,1]
/// in y, stacked in z) with n1, n2, n3 divisions, two contact pairs (lower/middle, middle/upper); the middle
/// and the upper block are held like the upper block of the two-block case, at their own top corners. The
/// exact solution is the same linear field, with the pressure p at both interfaces.

#include <memory>
#include <string>
#include <vector>

#include "support/model_case.hpp"
#include "support/solve_case.hpp"

namespace symcontact::testing {

struct ContactPatchCase {
  int dim = 2;                     ///< 2: two blocks; 3: two cubes
  int n1 = 4, n2 = 5;              ///< divisions per side of the lower and the upper block
  int order = 1;                   ///< Lagrange order
  std::string mode = "symmetric";  ///< "symmetric" or "one-pass" (slave: surface b, the upper block's bottom unless swapped)
  int n3 = 0;                      ///< > 0: a third block on top with n3 divisions per side
  bool swap = false;               ///< declare the bodies and the pairs in reverse order, each pair's a and b swapped
  double mu = -1.0;                ///< < 0: frictionless; ≥ 0: Coulomb friction with this coefficient
  double alpha = 0.0;              ///< friction regularisation length; 0: automatic
  /// 2D, two blocks: one body "blocks" (both surfaces) whose two blocks touch at y = 1, with their own nodes
  /// there (coincident where the divisions meet), held by one self-contact pair on the group "interface" (both
  /// faces); the lower block's supports as in the two-body case, u_x = 0 at (0, 2) on the same body.
  bool one_body = false;
  /// 2D, two blocks: Young's modulus and Poisson's ratio of the upper block (the lower's are 1 and 0.3). With
  /// one_body, a second material of the same body on the cells of "upper" ([[body.material]] per group). The
  /// exact field is then the same in the lower block and, in the upper one, u_x = ν_u (1 + ν_u) p x / E_u,
  /// u_y = −(1 − ν²) p − (1 − ν_u²) p (y − 1) / E_u. Unless ν_u (1 + ν_u) / E_u = ν (1 + ν), the blocks spread
  /// sideways by different amounts: a frictionless slip, exact in small sliding only (geometry =
  /// "reference"), since in the current geometry the wider block's edge then overhangs the other's.
  double upper_E = 1.0, upper_nu = 0.3;
  std::string geometry = "current";  ///< [[contact]] geometry: "current" or "reference" (small sliding)
  /// The blocks meshed with quadrilaterals (2D, Recombine: Quad4, or Quad9 at order 2) or hexahedra (3D,
  /// n³ transfinite: Hex8 or Hex27), by name ("lower", "upper", "middle"); the others keep their simplices.
  std::vector<std::string> quad_blocks;
  /// With quad_blocks at order 2: the incomplete second order (Mesh.SecondOrderIncomplete = 1: Quad8, Hex20).
  bool serendipity = false;
};

struct ContactPatchErrors {
  double displacement = 0.0;   ///< max nodal |u − u_exact| / max |u_exact|
  double pressure = 0.0;       ///< max over the contact nodes of both sides of |p − p_exact| / p_exact
  double tangential = 0.0;     ///< max |tangential traction| / p_exact over the contact nodes
  double equilibrium = 0.0;    ///< |Σ support reactions + Σ applied loads| / |Σ applied loads| (vectors)
  double applied_load = 0.0;   ///< |Σ applied loads| (= p × the top's area)
  int geometry_iterations = 0, ipopt_iterations = 0, coulomb_iterations = 0;
};

/// The Gmsh file of the two blocks (physical groups: surfaces "lower", "upper"; curves "bottom",
/// "lower_top", "upper_bottom", "top"; points "origin", "upper_corner"). In 3D: volumes "lower", "upper";
/// surfaces "bottom", "lower_top", "upper_bottom", "top"; points "origin", "lower_x" (1, 0, 0),
/// "upper_corner" (0, 0, 2), "upper_x" (1, 0, 2). With n3 > 0, three blocks "lower", "middle", "upper":
/// faces "bottom", "lower_top", "middle_bottom", "middle_top", "upper_bottom", "top"; points "origin"
/// (and "lower_x"), "middle_corner" (0, 2) (and "middle_x" (1, 0, 2)), "upper_corner" (0, 3) (and
/// "upper_x" (1, 0, 3)). `one_body` (2D, two blocks): the surface "blocks" (both) and the curve "interface"
/// (the lower block's top and the upper block's bottom) as well. The 3D corner groups are bounding boxes: they also hold the coincident corner
/// of the block above, which a body's restriction of the group leaves out.
std::string contact_patch_geo(int n1, int n2, int dim = 2, int n3 = 0, bool one_body = false);

/// The problem file (mesh "blocks.geo" in the same folder).
std::string contact_patch_toml(const ContactPatchCase& c);

/// The patch's model at its one load step, for tests of the solver stages: both files written into `folder`,
/// the model built (quietly) and set to step 0; `fixed` gets that step's Dirichlet conditions.
std::unique_ptr<ModelCase> contact_patch_model(const ContactPatchCase& c, const std::filesystem::path& folder,
                                               FixedDofs& fixed);

/// Writes both files into a temporary folder and solves.
std::unique_ptr<SolvedCase> contact_patch_solve(const ContactPatchCase& c);

/// The errors of a solution of `c` against the exact solution (pressures over every pair and side).
ContactPatchErrors contact_patch_errors(const ContactPatchCase& c, const SolvedCase& s);

/// Solves and measures: contact_patch_errors(c, *contact_patch_solve(c)).
ContactPatchErrors contact_patch_errors(const ContactPatchCase& c);

/// "n4_5_P1_symmetric" ("n4_5_3_…" with a third block; + "_swapped", "_mu0.3", "_one_body", "_reference",
/// "_quad_lower_upper" (+ "8" with serendipity; "_hex_…", "_hex20_…" in 3D); "3D_" first in 3D): a GoogleTest
/// parameter name.
std::string contact_patch_name(const ContactPatchCase& c);

}  // namespace symcontact::testing
