#pragma once
/// \file external_load.hpp
/// External work terms, E(u) = −s fᵀu with f = ∫_Ω b·v + ∫_Γ t·v (talk eq. 5) and s the load factor
/// of the current step; plus the routines that integrate f from body forces and surface tractions.

#include <functional>
#include <string>
#include <vector>

#include "symcontact/energy/energy_term.hpp"
#include "symcontact/fem/analysis_model.hpp"
#include "symcontact/fem/dof_map.hpp"
#include "symcontact/mesh/mesh.hpp"

namespace symcontact {

class LinearLoad : public EnergyTerm {
 public:
  LinearLoad(std::string name, VectorXd f) : name_(std::move(name)), f_(std::move(f)) {}
  std::string name() const override { return name_; }
  double value(const VectorXd& u) const override { return -scale_ * f_.dot(u); }
  void add_gradient(const VectorXd&, VectorXd& g) const override { g -= scale_ * f_; }
  void add_hessian(const VectorXd&, MatrixSink&) const override {}
  bool hessian_is_constant() const override { return true; }
  void set_scale(double s) { scale_ = s; }
  double scale() const { return scale_; }
  const VectorXd& load() const { return f_; }  ///< f at scale 1
  /// Replaces f (a load that is not proportional to the load factor: Model::set_step).
  void set_load(VectorXd f) { f_ = std::move(f); }

 private:
  std::string name_;
  VectorXd f_;
  double scale_ = 1.0;
};

/// b(x): writes dim components of the force per unit volume at x (dim coordinates).
using BodyForceFn = std::function<void(const double* x, double* b)>;
/// t(x, n): writes dim components of the traction at boundary point x with outward unit normal n.
using TractionFn = std::function<void(const double* x, const double* n, double* t)>;

/// f_(a,i) = ∫_Ω b_i N_a, with a quadrature of degree `degree` (+ element order). In an axisymmetric
/// `model`, dΩ = 2π r dA (the whole ring; analysis_model.hpp), and the quadrature's degree is one more.
VectorXd body_force_vector(const Mesh& mesh, const DofMap& dofs, int body, const BodyForceFn& b,
                           AnalysisModel model = AnalysisModel::kPlaneStrain, int degree = 2);

/// f_(a,i) = ∫_Γ t_i N_a over the facets of `group` (outward-oriented by Mesh::locate_facets()); dΓ = 2π r ds
/// in an axisymmetric `model`, as above.
VectorXd boundary_load_vector(const Mesh& mesh, const DofMap& dofs, int body, const FacetGroup& group,
                              const TractionFn& t, AnalysisModel model = AnalysisModel::kPlaneStrain,
                              int degree = 2);

/// Measure (length in 2D, area in 3D) of a facet group, and ∫ n over it, with the quadrature of
/// boundary_load_vector() at the same `degree` (degree + facet order): a uniform traction t = F / measure
/// then has nodal forces summing to F to round-off (Σ_a N_a = 1 at every quadrature point), on curved
/// (P2) facets too, where the measure itself is only that quadrature's.
/// In an axisymmetric `model`, the area of the surface of revolution and ∫ n dS over it.
double facet_group_measure(const Mesh& mesh, const FacetGroup& group, Eigen::VectorXd* normal_integral = nullptr,
                           AnalysisModel model = AnalysisModel::kPlaneStrain, int degree = 2);

/// f_(a,i) = F_i at every node a of `nodes` (a concentrated force, per unit thickness in 2D, and in an
/// axisymmetric model the total force on the circle through the node): dim components of F.
VectorXd point_load_vector(const DofMap& dofs, int body, const std::vector<Index>& nodes, const double* F);

}  // namespace symcontact
