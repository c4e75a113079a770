#pragma once
/// \file problem_spec.hpp
/// The problem as the user wrote it: plain data read from the TOML problem file (problem_reader.hpp),
/// before any mesh is loaded. Every item remembers `key`, the TOML path it came from (for example
/// "body[2].dirichlet[1].boundary"), so that errors found later (a missing physical group) can name it.
///
/// Load histories: every load and imposed displacement is multiplied, at load step k, by its own
/// `factors[k]` when given, else by the problem's `steps.load_factors[k]`. A value given as an expression
/// (LoadValue) is not multiplied: it is evaluated with that factor as its variable t.

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "symcontact/contact/contact_geometry.hpp"
#include "symcontact/fem/analysis_model.hpp"
#include "symcontact/solvers/load_step.hpp"

namespace symcontact {

/// A body's material. `model` is "linear_elastic", "neo_hookean" or "mooney_rivlin" (finite strain,
/// materials/hyperelastic.hpp). Parameters: (E, nu) for every model, or the model's own constants
/// (mu, lambda for neo_hookean; c1, c2, kappa for mooney_rivlin), exactly one set.
struct MaterialSpec {
  std::string key;             ///< e.g. "body[0].material", or "body[0].material[1]" in a list
  /// The physical group of cells (of the body's dimension) this material fills; empty: the whole body.
  std::string group;
  std::string model = "linear_elastic";
  double young = 0.0;          ///< E > 0, [stress]; with own_constants, the small-strain equivalent
  double poisson = 0.0;        ///< nu in (-1, 0.5); with own_constants, the small-strain equivalent
  /// True when the model's own constants were given instead of (E, nu); young/poisson then hold the
  /// small-strain equivalent (used for the linear-elastic stress output).
  bool own_constants = false;
  double mu = 0.0;             ///< neo_hookean: shear modulus > 0, [stress]
  double lambda = 0.0;         ///< neo_hookean: Lamé lambda, lambda + 2 mu / 3 > 0, [stress]
  double c1 = 0.0, c2 = 0.0;   ///< mooney_rivlin: >= 0, c1 + c2 > 0, [stress]
  double kappa = 0.0;          ///< mooney_rivlin: bulk modulus > 0, [stress]
};

/// A value the problem file gives as a number or as an expression (a Dirichlet component, a pressure, a
/// traction component). At load factor t and reference point X: `number` × t, or the expression
/// (core/expression.hpp) of (X, t) as written.
struct LoadValue {
  double number = 0.0;      ///< the value at load factor 1 (without an expression)
  std::string expression;   ///< non-empty: an expression of x, y, z, t, checked to compile by the reader
  bool is_expression() const { return !expression.empty(); }
};

/// u_i = value_i at the step's factor on a named boundary (facet group) or node group; unset components
/// are free.
struct DirichletSpec {
  std::string key;
  std::string group;
  std::array<std::optional<LoadValue>, 3> value;  ///< ux, uy, uz
  std::vector<double> factors;                    ///< per-step multipliers (empty: the global ones)
};

/// How a [[body.traction]] states its load: the traction itself, or the resultant it must have.
enum class TractionInput { kTraction, kTotalForce };

/// A uniform surface traction t (force per unit area, or per unit length in 2D) on a named boundary,
/// given as t (`traction`) or as its resultant F (`total_force`): then t = F / |Γ_h|, |Γ_h| the measure
/// of the meshed facets (facet_group_measure(), energy/external_load.hpp), so that Σ of the nodal forces
/// is F whatever the faceting.
struct TractionSpec {
  std::string key;
  std::string group;
  TractionInput input = TractionInput::kTraction;
  /// dim components: t (kTraction: numbers or expressions) or F (kTotalForce: numbers)
  std::vector<LoadValue> traction;
  std::vector<double> factors;
};

/// A force (per unit thickness in 2D) at every node of a physical point group (Gmsh dimension 0):
/// a group of n points receives n × force in total.
struct PointLoadSpec {
  std::string key;
  std::string group;
  std::vector<double> force;  ///< dim components
  std::vector<double> factors;
};

/// A pressure p (follows the outward normal inwards: t = −p n) on a named boundary.
struct PressureSpec {
  std::string key;
  std::string group;
  LoadValue pressure;
  std::vector<double> factors;
};

struct BodySpec {
  std::string key;                ///< "body[i]"
  std::string name;               ///< unique; used in output file names
  std::string mesh_file;          ///< as written in the problem file
  std::string mesh_path;          ///< resolved against the problem file's folder
  /// Numbers set in the .geo before it is meshed, as Gmsh's `-setnumber name value` (mesh_parameters).
  std::map<std::string, double> mesh_parameters;
  std::string group;              ///< physical group of cells forming the body; empty: all cells of the file
  /// One material for the whole body (group empty), or one per physical group of its cells
  /// ([[body.material]] tables, each with `group`); all linear elastic or all hyperelastic.
  std::vector<MaterialSpec> materials;
  std::vector<double> body_force; ///< force per unit volume, dim components (empty: none)
  std::vector<double> body_force_factors;
  std::vector<DirichletSpec> dirichlet;
  std::vector<TractionSpec> tractions;
  std::vector<PressureSpec> pressures;
  std::vector<PointLoadSpec> point_loads;
};

/// A rigid obstacle: analytic ("plane", "circle" in 2D / "sphere" in 3D) or meshed ("mesh": the facets
/// of a boundary group of a mesh file, which stay fixed).
struct ObstacleSpec {
  std::string key;                 ///< "contact[i].obstacle"
  std::string type;                ///< "plane" | "circle" | "sphere" | "mesh"
  std::vector<double> point;       ///< plane: a point of it (dim components)
  std::vector<double> normal;      ///< plane: normal pointing towards the body (dim components, nonzero)
  std::vector<double> center;      ///< circle/sphere: centre
  double radius = 0.0;             ///< circle/sphere: > 0
  bool inside = false;             ///< circle/sphere: the body lies inside (a rigid hole)
  std::string mesh_file, mesh_path;///< mesh: file as written / resolved
  std::string boundary;            ///< mesh: the facet group forming the rigid surface
};

/// One contact pair: surface a (a body's boundary group) against surface b of another (or the same)
/// body, or against a rigid obstacle.
struct ContactSpec {
  std::string key;                 ///< "contact[i]"
  std::string name;                ///< unique; default "contact<i>" (0-based)
  std::string body_a, boundary_a;  ///< from a = "body.boundary"
  std::string body_b, boundary_b;  ///< from b = "body.boundary"; empty with an obstacle
  std::optional<ObstacleSpec> obstacle;
  std::string mode = "symmetric";  ///< "symmetric" (both sides in turn slave) | "one-pass"
  std::string slave = "a";         ///< one-pass: which surface is the slave, "a" or "b"
  double search_distance = 0.0;    ///< > 0; 0: automatic (see docs/input.md)
  /// Friction on the pair (METHOD.md, "Friction"): "none", "tresca" (threshold `tau`, [stress]) or
  /// "coulomb" (coefficient `mu`, solved as a fixed point on the Tresca threshold τ = μ p).
  std::string friction = "none";
  double mu = 0.0;                 ///< coulomb: ≥ 0
  double tau = 0.0;                ///< tresca: ≥ 0
  double alpha = 0.0;              ///< regularisation of |v| by sqrt(|v|² + α²) [length]; > 0; 0: automatic
  /// "current" (finite sliding: the geometry fixed point) | "reference" (small sliding: the geometry of X,
  /// the gap linearised there once; contact/contact_geometry.hpp).
  ContactGeometry geometry = ContactGeometry::kCurrent;
};

struct OutputSpec {
  bool vtu = true;        ///< VTU per body per step + PVD collection
  bool summary = true;    ///< summary.json
};

/// How the contact steps' linear algebra is done ([contact_solver] linear_solver): the serial solver with sparse
/// Cholesky factors ("direct"), the distributed path with conjugate gradients and algebraic multigrid
/// ("iterative", docs/distributed.md), or the first unless its factor is predicted not to fit in memory
/// ("automatic", the default; the rule: docs/distributed.md).
enum class LinearSolverChoice { kAutomatic, kDirect, kIterative };

struct ProblemSpec {
  std::string file;                 ///< path of the problem file (for messages)
  std::string title;
  int dim = 2;                      ///< 2 or 3
  AnalysisModel model = AnalysisModel::kPlaneStrain;
  int order = 1;                    ///< Lagrange order 1 or 2
  double mesh_size = 0.0;           ///< maximum element size for .geo meshing; 0: the .geo's own sizes
  std::vector<BodySpec> bodies;
  std::vector<double> load_factors{1.0};  ///< one entry per load step
  std::vector<ContactSpec> contacts;
  /// The [contact_solver] and [ipopt] tables, read straight into the solver's settings under the file's names
  /// (solvers/load_step.hpp LoadStepOptions; its `friction.contact.ipopt` holds [ipopt] by value type).
  LoadStepOptions contact_solver;
  LinearSolverChoice linear_solver = LinearSolverChoice::kAutomatic;
  OutputSpec output;
};

}  // namespace symcontact
