#pragma once
/// \file friction_term.hpp
/// Regularised Tresca friction as one more energy term (talk eq. 16–18, METHOD.md "Friction"):
///
///   j_{α,τ}(u) = Σ_q w_q τ_q η_α(s_q(u)),   η_α(v) = sqrt(|v|² + α²),
/// (the solver uses one point per slave node, w_q = its lumped area: nodal_contact_points()),
///   s_q(u) = P_q [ (u_s(ξ_q) − u⁰_s(ξ_q)) − (u_m(η_q) − u⁰_m(η_q)) ],   P_q = I − n̄_q n̄_qᵀ,
///
/// over the integration points of ONE constraint family of the pair (the interface is counted once,
/// also in the symmetric formulation), with the projections ξ_q, η_q and normals n̄_q frozen by the
/// geometry step. u⁰ is the displacement at the start of the load step: friction acts on the slip
/// increment of the step, so loading paths are respected. For an obstacle u_m = 0.
///
/// Derivatives (r = sqrt(|s|² + α²) ≥ α > 0, so nothing divides by a small slip):
///   ∇ = w τ Bᵀ s / r,   ∇² = w τ Bᵀ P (I − s sᵀ / r²) P B / r,   B the relative-displacement map.
/// The tangential traction on the slave is σ_T = −τ s / r (talk, regularised Tresca law).

#include <string>
#include <vector>

#include "symcontact/contact/contact_points.hpp"
#include "symcontact/energy/energy_term.hpp"
#include "symcontact/fem/dof_map.hpp"

namespace symcontact {

class FrictionTerm : public EnergyTerm {
 public:
  /// `master` is null for an obstacle. `tau` has one threshold per point (≥ 0), alpha > 0.
  FrictionTerm(std::string name, const ContactSurface& slave, const ContactSurface* master,
               std::vector<ContactPoint> points, std::vector<double> tau, double alpha, const DofMap& dofs,
               const VectorXd& u_start);
  std::string name() const override { return name_; }
  double value(const VectorXd& u) const override;
  void add_gradient(const VectorXd& u, VectorXd& g) const override;
  void add_hessian(const VectorXd& u, MatrixSink& sink) const override;
  bool hessian_is_constant() const override { return false; }

  /// Slip increment s_q at every point (3 components, z = 0 in 2D).
  std::vector<Eigen::Vector3d> slips(const VectorXd& u) const;
  const std::vector<ContactPoint>& points() const { return points_; }

 private:
  struct Local {
    std::vector<Index> dofs;   ///< slave facet DOFs then master facet DOFs
    Eigen::MatrixXd B;         ///< dim × dofs: relative displacement = B u_loc
    Eigen::MatrixXd P;         ///< dim × dim tangential projector
    Eigen::VectorXd s0;        ///< P B u⁰_loc
    double wt = 0.0;           ///< w τ
  };
  Eigen::VectorXd slip(const Local& l, const VectorXd& u) const;

  std::string name_;
  std::vector<ContactPoint> points_;
  std::vector<Local> local_;
  double alpha_;
  int dim_;
};

}  // namespace symcontact
