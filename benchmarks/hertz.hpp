#pragma once
/// \file hertz.hpp
/// The Hertz contact benchmark problems of examples/hertz_2d (VALIDATION.md, V1) and examples/hertz_3d
/// (V2), solved through the library exactly as a problem file is (parse_problem → Model::build →
/// solve_contact with contact_options()), at a chosen fine mesh size h, with the accuracy against the
/// closed form and the Cholesky floor of the same stiffness.
///
///  - kCylinderOnPlane  (hertz_2d/cylinder_on_plane.toml): half cylinder R = 1 on the rigid plane y = 0.
///  - kTwoCylinders     (hertz_2d/two_cylinders.toml): two elastic half cylinders R = 1 touching at the origin.
///  - kSphereOnPlane    (hertz_3d/sphere_on_plane.toml): quarter sphere R = 1 on the rigid plane z = 0, P1 Tet4.
///  - kTwoSpheres       (hertz_3d/two_spheres.toml): two elastic quarter spheres R = 1 touching at the origin.
/// All: E = 1, ν = 0.3 (2D: plane strain), nominal P = 0.01 on the whole body; the half (2D) or quarter
/// (3D) model carries P/2, resp. P/4, on its flat cut. E* = E / (1 − ν²), R_eff = 1 on the plane; two
/// bodies give R_eff = 1/2 and E* halved, hence the same a and p0:
///   2D: a = sqrt(4 P R_eff / (π E*)) = 0.107641,  p0 = 2 P / (π a)   = 0.059143;
///   3D: a = (3 P R_eff / (4 E*))^(1/3) = 0.189686, p0 = 3 P / (2 π a²) = 0.132701.
/// The closed form is evaluated at the load actually applied, P_h = (2, resp. 4) × the resultant of the
/// model's external load (as tests/validation/test_hertz_3d.cpp does): in 3D the meshed cut is a polygon
/// inscribed in the quarter disk, 0.1–1 % smaller (reported as load_error); in 2D the cut is straight and
/// P_h = P to round-off.
///
/// Mesh size: the example's .geo is included, unchanged, from a wrapper "h = …; Include "…";" written
/// into a temporary directory (the tests do the same). The 2D .geo keeps its coarse size H = 0.08 beyond
/// distance 0.6 of the contact point and size h within 0.2 of it, so DOFs grow as h⁻²; the 3D .geo keeps
/// H = 0.25 beyond distance 0.8 and h within 0.25, so DOFs grow as about h⁻³.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "elastic_block.hpp"
#include "symcontact/model/model.hpp"
#include "symcontact/solvers/contact_solver.hpp"

namespace symcontact::bench {

enum class HertzCase { kCylinderOnPlane, kTwoCylinders, kSphereOnPlane, kTwoSpheres };

/// "hertz2d", "hertz2d-cylinders", "hertz3d", "hertz3d-spheres" (the --case names).
std::string hertz_case_name(HertzCase c);
/// One line saying what the case is ("cylinder on a rigid plane, plane strain, P1, half model").
std::string hertz_case_description(HertzCase c);
/// 2 or 3.
int hertz_dimension(HertzCase c);
/// Copies of the model that make up the whole body: 2 (half model, 2D) or 4 (quarter model, 3D).
int hertz_symmetry_factor(HertzCase c);

/// Closed form of the cases (see the file comment) for a load P on the whole body.
struct HertzReference {
  static constexpr double kNominalLoad = 0.01;  ///< P of the examples, the resultant on the whole body
  double load = kNominalLoad;                   ///< P the closed form is evaluated at
  double a = 0.0;                               ///< radius (3D) or half-width (2D) of the contact zone
  double p0 = 0.0;                              ///< peak pressure
};
HertzReference hertz_reference(HertzCase c, double load = HertzReference::kNominalLoad);

/// One solved instance. Not copyable (the model refers to the spec).
struct HertzRun {
  HertzCase which = HertzCase::kCylinderOnPlane;
  double h = 0.0;
  ProblemSpec spec;
  std::unique_ptr<Model> model;
  PhaseTimes build_times;      ///< "meshing" (Gmsh), "setup" (DOFs, energy, contact surfaces)
  FixedDofs fixed;             ///< the problem's Dirichlet conditions
  VectorXd u;                  ///< solution, full DOF vector
  SolveReport report;
  double solve_wall = 0.0;     ///< wall time of solve_contact() as a whole, s
  double solve_cpu = 0.0;      ///< process CPU time of solve_contact() as a whole, s

  // Accuracy (side a of the first contact pair: the cylinder/sphere, resp. the upper one).
  double load = 0.0;           ///< P_h: symmetry factor × the resultant of the external load (see the file comment)
  double p0 = 0.0;             ///< largest nodal pressure
  double a = 0.0;              ///< largest horizontal distance to the axis of a node with pressure > 1e-3 p0
                               ///< (nodal: known to about one element)
  double force = 0.0;          ///< |vertical contact force| on the model (P_h / symmetry factor expected)
  double min_constraint = 0.0; ///< min (A u + b) at the last linearisation (≥ 0 up to round-off)
  Index surface_nodes = 0;     ///< nodes of the contact surfaces of the first pair (the search's size)
  Index surface_facets = 0;    ///< facets of the same
  double search_distance = 0.0;  ///< of the first pair, as resolved by the model (automatic unless given)

  /// search + assembly + optimizer + polish + condensation of report.times (the contact solve proper).
  double contact_seconds() const;
  /// The closed form at this run's applied load.
  HertzReference reference() const { return hertz_reference(which, load); }
};

/// Called with the built model right before the contact solve (e.g. check_hertz_fits); may throw to skip it.
using BeforeSolve = std::function<void(const HertzRun&)>;

/// Writes the wrapper .geo and a copy of the example's TOML (pointing at it) into `work_dir`, builds the
/// model and solves it (solve_hertz_model). `examples_dir` is the examples/ folder of the source tree.
/// Throws what the library throws (InputError, SolveError) and what `before_solve` throws.
/// `condense` false switches the static condensation off (contact_solver.static_condensation), `dual` chooses
/// how the condensed problem is solved (contact_solver.subproblem_solver);
/// `search_distance` > 0 sets the contact pair's search_distance (default: the example's, automatic).
std::unique_ptr<HertzRun> solve_hertz(HertzCase which, double h, const std::string& examples_dir,
                                      const std::string& work_dir, bool condense = true, double search_distance = 0.0,
                                      const BeforeSolve& before_solve = nullptr,
                                      SubproblemSolver dual = SubproblemSolver::kDualInteriorPoint);

/// Builds run.model from run.spec (a single load step, one contact pair whose side a is the loaded body),
/// calls `before_solve` (when set), solves it with the solver settings `symcontact run` derives from the
/// file (contact_options()), condensation off when `condense` is false, the dual solve off when `dual` is
/// false, timing solve_contact() as a whole,
/// and fills the accuracy fields of `run`. Used by solve_hertz() and by the FreeFEM side by side
/// (freefem_peer.cpp).
void solve_hertz_model(HertzRun& run, bool condense = true, const BeforeSolve& before_solve = nullptr,
                       SubproblemSolver dual = SubproblemSolver::kDualInteriorPoint);

/// Throws FactorTooLarge (elastic_block.hpp) when the contact solve of `run` would not fit in the memory
/// available now, before it starts: the peak of solvers/memory_prediction.hpp (predicted_direct_peak_bytes,
/// fitted to this solve) from CHOLMOD's analysis of the floor's K_ff, m taken as the number of contact-surface
/// nodes (the condensed set on a rigid plane: one u_z per node; a lower bound with two elastic bodies). The
/// check is meant to refuse a size that cannot fit before it runs for an hour and is killed. Returns the
/// predicted nnz(L).
double check_hertz_fits(const HertzRun& run);

/// The contact search proper at the solution run.u, timed on its own: for every contact family, the
/// current positions of its surfaces, prepare_master() (smoothed normals, bounding volume hierarchy) and
/// contact_points() (projections, 3D segmentation by clipping, quadrature points, gaps); the minimum
/// wall time over `repeat` runs, in s. The "search" phase of solve_contact() also assembles the gap
/// constraint matrix A (rows × all DOFs) and expands the free DOFs to the full vector, which costs
/// O(DOFs of the volume); this measures only what grows with the contact surfaces.
double time_contact_search(const HertzRun& run, int repeat);

/// The Cholesky floor of run.model: K_ff of the whole energy (all bodies), factorised and solved for the
/// external load. The free DOFs are those of the contact problem except that the vertical component
/// (u_y in 2D, u_z in 3D) is additionally fixed at the node(s) at the initial contact point (the origin)
/// of every body: without contact the cylinder/sphere (and the upper one of the two-body cases) is free
/// to translate vertically and K_ff is singular. One (resp. two) fewer row than the contact problem; no
/// regularisation. `pinned` receives the number of DOFs so fixed.
CholeskyFloor measure_hertz_floor(const HertzRun& run, int repeat, Index& num_free, int& pinned);

}  // namespace symcontact::bench
