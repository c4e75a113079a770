#pragma once
/// \file rescale_problem.hpp
/// Test tool: rewrites a problem file into another consistent system of units, so that a test can solve
/// the same physical problem twice and compare dimensionless results (every stopping rule of the solver
/// must be relative to the problem's own scales: docs/input.md, "Units").
///
/// A change of units multiplies every length by `length` and every force by `force` (from m–N–Pa to
/// mm–N–MPa: length = 1e3, force = 1). Each key of docs/input.md is multiplied by its unit's factor:
///   [length]                 ux uy uz, mesh_size, search_distance, alpha, obstacle point / center / radius
///   [stress] = F / L²        E, mu and lambda of a material, c1 c2 kappa, traction, pressure, Tresca tau
///   [force] / [length]³      body_force
/// and dimensionless keys (nu, Coulomb mu, normal, factors, tolerances, [ipopt]) are left as they are. An
/// expression (docs/loads.md) of a Dirichlet value, a pressure or a traction is rewritten by
/// scale_expression(): its value × the key's factor, its coordinates x, y, z in the new lengths. In
/// 2D, forces are per unit thickness, so reactions scale as force / length there and as force in 3D.
///
/// The meshes are written anew, as ASCII MSH 4.1 files with their coordinates multiplied by `length`: a
/// `.geo` is meshed by Gmsh first, at the problem's order, mesh_size and the body's mesh_parameters (which then
/// leave the problem), and written with its elements as
/// meshed (P2 edge nodes where Gmsh placed them). Calling it with length = force = 1 gives the reference
/// the rescaled problem is compared with: both then solve the very same mesh.

#include <string>

namespace symcontact::testing {

struct UnitChange {
  double length = 1.0;  ///< new length unit per old one (m → mm: 1e3)
  double force = 1.0;   ///< new force unit per old one
  double stress() const { return force / (length * length); }
};

/// Edits of a problem file for the zoo of tests/zoo (none by default).
struct ProblemVariant {
  int order = 0;           ///< > 0: [problem] order
  double coulomb_mu = -1;  ///< ≥ 0: every [[contact]] with Coulomb friction of this μ (its tau and alpha dropped)
  double mesh_size = 0;    ///< > 0: [problem] mesh_size (the largest element size of .geo meshes)
  /// > 0: [steps] count, for the first steps of a problem whose loads are given at step numbers (`factors`
  /// with `at`), which the count leaves as they are.
  int step_count = 0;
  /// Non-empty: Gmsh statements read before each `.geo` mesh of a body (a wrapper `.geo` in the variant's
  /// folder that sets them and then Includes the original), e.g. "h = 0.04;" for a file that sizes its
  /// elements by `If (!Exists(h)) h = …; EndIf`.
  std::string geo_definitions;
};

/// The expression f(x, y, z, t) of a value in the old units rewritten for the new ones: factor · f(x/length,
/// y/length, z/length, t), as text ("1000*(0.1*(x/1000)*t)" for f = "0.1*x*t", factor = length = 1e3). The
/// names x, y and z are replaced where they stand alone, never inside a longer name or a number.
std::string scale_expression(const std::string& text, double factor, double length);

/// Writes `out_dir`/problem.toml: the problem with every mesh path made absolute and `variant` applied; the
/// meshes are not copied. Returns its path. Throws std::runtime_error when the problem cannot be read.
std::string write_variant(const std::string& problem_path, const ProblemVariant& variant, const std::string& out_dir);

/// Writes `out_dir`/problem.toml and one `<mesh>.msh` per mesh file the problem names, in the units of
/// `change`. Returns the path of the new problem file. Throws std::runtime_error when the problem cannot be
/// read or a mesh cannot be made or written.
std::string rescale_problem(const std::string& problem_path, const UnitChange& change, const std::string& out_dir);

}  // namespace symcontact::testing
