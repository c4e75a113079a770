#pragma once
/// \file model.hpp
/// The discrete problem built from a ProblemSpec: the bodies' meshes and materials, the global DOF
/// numbering, the total energy (elastic terms + external loads), and the Dirichlet conditions of each
/// load step. Every lookup that can fail on user input (a physical group, a component) fails here, with
/// the problem file and key, before anything is solved or written.

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "symcontact/contact/contact_set.hpp"
#include "symcontact/core/expression.hpp"
#include "symcontact/core/log.hpp"
#include "symcontact/core/timer.hpp"
#include "symcontact/energy/energy_sum.hpp"
#include "symcontact/energy/external_load.hpp"
#include "symcontact/fem/dof_map.hpp"
#include <optional>

#include "symcontact/materials/hyperelastic.hpp"
#include "symcontact/materials/linear_elastic.hpp"
#include "symcontact/mesh/gmsh_io.hpp"
#include "symcontact/mesh/mesh.hpp"
#include "symcontact/model/problem_spec.hpp"
#include "symcontact/solvers/fixed_dofs.hpp"

namespace symcontact {

/// How .geo files are meshed, beyond the problem file (the CLI's --mesh-size, --allow-large-mesh and
/// --allow-geo-commands).
struct MeshingOverrides {
  double mesh_size = 0.0;  ///< > 0 replaces spec.mesh_size
  /// The limit on the predicted cell count of a .geo meshed with a size (gmsh_io.hpp); ≤ 0: none.
  double max_predicted_cells = kDefaultMaxPredictedCells;
  GeoCommands geo_commands = GeoCommands::kRefuse;
};

struct Body {
  std::string name;
  const BodySpec* spec = nullptr;
  Mesh mesh;
  /// The laws of the body's materials, in the order of spec->materials: the small-strain law of each (for
  /// every body), and the finite-strain law of each for a hyperelastic body (empty for a linear one).
  std::vector<LinearElastic> materials;
  std::vector<Hyperelastic> hyperelastic;
  /// The material of each cell (an index into `materials`); empty when the body has one material.
  std::vector<int> cell_material;
};

/// A LoadValue ready to evaluate: at reference point X (dim coordinates) and load factor t, number × t, or
/// the compiled expression of (X, t).
struct CompiledValue {
  double number = 0.0;
  std::shared_ptr<const Expression> expression;  ///< null: the number
  double at(const double* X, int dim, double t) const {
    return expression ? expression->at(X, dim, t) : number * t;
  }
};

/// One named Dirichlet boundary of a body ([[body.dirichlet]] entry), for the imposed values and the
/// reaction forces.
struct DirichletBoundary {
  int body = 0;
  std::string name;            ///< the group name
  std::vector<Index> nodes;
  const DirichletSpec* spec = nullptr;
  std::array<std::optional<CompiledValue>, 3> values;  ///< ux, uy, uz; unset: free
};

/// What a surface load's values are: the traction vector, or a pressure p (traction −p n).
enum class SurfaceLoad { kTraction, kPressure };

class Model {
 public:
  /// Reads or meshes every body's mesh and builds the energy. Throws InputError on bad input.
  /// `meshing.mesh_size` > 0 replaces spec.mesh_size.
  static std::unique_ptr<Model> build(const ProblemSpec& spec, const Logger& log, PhaseTimes& times,
                                      const MeshingOverrides& meshing = {});

  const ProblemSpec& spec() const { return spec_; }
  int dim() const { return spec_.dim; }
  int num_steps() const { return static_cast<int>(spec_.load_factors.size()); }
  const DofMap& dofs() const { return dofs_; }
  const std::vector<std::unique_ptr<Body>>& bodies() const { return bodies_; }
  const EnergySum& energy() const { return energy_; }
  const std::vector<DirichletBoundary>& dirichlet_boundaries() const { return boundaries_; }
  /// The contact pairs (empty without [[contact]]).
  const ContactSet& contacts() const { return contacts_; }
  /// Index of the body named `name`, or −1.
  int body_index(const std::string& name) const;

  /// Sets every load term to its factor at load step `step` (0-based). With `fraction` < 1, at that
  /// fraction of the way from step − 1 (the unloaded start for step 0) to step: every factor is
  /// interpolated linearly between the two steps' factors (sub-steps of an automatic step cut).
  void set_step(int step, double fraction = 1.0);
  /// Dirichlet values at load step `step` (at `fraction` of it, as set_step).
  FixedDofs fixed_dofs(int step, double fraction = 1.0) const;
  /// Reaction force of every Dirichlet boundary (dirichlet_boundaries() order): the sum of ∇E(u)
  /// (= K u − f, the force the support exerts on the body) over the DOFs that boundary holds. A DOF
  /// held by several conditions counts for the last one only, so the reactions add up to the total.
  std::vector<Eigen::VectorXd> reactions(const FixedDofs& fixed, const VectorXd& gradient) const;
  /// The applied external load vector at the current step (Σ s_k f_k).
  VectorXd external_load() const;
  /// What the input asks that is legal but likely a mistake (each also logged as a warning when the model
  /// was built): an axisymmetric body with nodes on the axis whose u_r is free.
  const std::vector<std::string>& warnings() const { return warnings_; }

 private:
  Model(const ProblemSpec& spec) : spec_(spec) {}
  const ProblemSpec& spec_;
  DofMap dofs_;
  std::vector<std::unique_ptr<Body>> bodies_;
  EnergySum energy_;
  struct LoadHandle {
    LinearLoad* term;
    std::vector<double> factors;
    /// The load vector at load factor t, for a load given by expressions (its term's scale then stays 1);
    /// empty: the term's vector is the load at factor 1, scaled by the factor.
    std::function<VectorXd(double t)> at;
  };
  std::vector<LoadHandle> loads_;
  std::vector<DirichletBoundary> boundaries_;
  ContactSet contacts_;
  std::vector<Mesh> rigid_meshes_;  ///< meshes of rigid meshed obstacles
  void build_contacts(const Logger& log, const MeshReadOptions& mesh_options);
  /// The load terms of body b: body force, tractions, pressures, point loads (InputError for a group
  /// the body's mesh lacks or of the wrong kind).
  void add_loads(int b);
  /// Adds the load of a [[body.traction]] (`values`: dim components) or [[body.pressure]] (`values`: one)
  /// of body b to the energy and to loads_.
  void add_surface_load(int b, const std::string& group, const std::string& key, const std::vector<LoadValue>& values,
                        const std::vector<double>& factors, SurfaceLoad kind);
  void add_dirichlet(int b, const DirichletSpec& ds);
  void warn_free_axis_nodes(const Logger& log);
  std::vector<std::string> warnings_;
};

/// The factor of load step `step`: own[step] when `own` is given, else global[step]; step −1 is the
/// unloaded start (0).
double step_factor(const std::vector<double>& own, const std::vector<double>& global, int step);
/// The factor at `fraction` of the way from step − 1 to step (linear between the two).
double step_factor(const std::vector<double>& own, const std::vector<double>& global, int step, double fraction);

}  // namespace symcontact
