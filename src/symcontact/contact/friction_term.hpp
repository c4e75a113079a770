#pragma once
/// \file friction_term.hpp
/// Regularised Tresca friction as one more energy term (talk eq. 16–18, METHOD.md "Friction"):
///
///   j_{α,τ}(u) = Σ_q w_q τ_q η_{α_q}(s_q(u)),   η_α(v) = sqrt(|v|² + α²),
/// (the solver uses one point per slave node, w_q = its lumped area: nodal_contact_points(); α_q its
/// regularisation length, ContactPair::regularisation_length()),
///   s_q(u) = P_q [ (u_s(ξ_q) − u⁰_s(ξ_q)) − (u_m(η_q) − u⁰_m(η_q)) ],   P_q = I − n̄_q n̄_qᵀ,
///
/// over the integration points of ONE constraint family of the pair (the interface is counted once,
/// also in the symmetric formulation), with the projections ξ_q, η_q and normals n̄_q frozen by the
/// geometry step. u⁰ is the displacement at the start of the load step: friction acts on the slip
/// increment of the step, so loading paths are respected. For an obstacle u_m = 0.
///
/// Nodal points on 6-node triangles (every point has ContactPoint::slave_node ≥ 0: nodal_contact_points(),
/// on a Tri6 slave). The pressure, and with it τ_i = μ p_i, is recovered in the test basis
/// φ_i = Σ_k T_ik N_k of the gap constraints (test_functions(), contact_surface.hpp; surface_tractions.hpp),
/// in which a nodal force F reads T F. The friction term measures the slip in that basis too: the slip
/// field Σ_k s_k N_k = Σ_i s̃_i φ_i has the coefficients s̃ = T⁻ᵀ s,
///   s̃_v = s_v (vertex v),   s̃_e = (s_e − c (s_v1 + s_v2)) / (1 − 2c) (edge node e of edge v1–v2),
/// c = kModifiedTri6Coefficient; a uniform slip keeps s̃ = s. Point q of edge node e then has the map
/// B̃_e = (B_e − c (B_v1 + B_v2)) / (1 − 2c), over the DOFs of the three nodes' points (each with its own
/// master side at its own projection), and the projector P_e of its own normal. Then j = Σ_i A_i τ_i η_α(s̃_i),
/// its force F = −T⁻¹ (A τ P s̃ / r) on the slave, and T F = −A_i τ_i P_i s̃_i / r_i at every node: the
/// recovered traction has |t_i| = τ_i |P_i s̃_i| / r_i ≤ τ_i, the nodal friction law in the basis that τ
/// lives in. With the standard nodal slips instead, T F mixes each vertex's friction force with c times
/// its edge neighbours', and |t_v| exceeds τ_v where the slip varies. A vertex without a point of its own
/// (it projects onto nothing) enters B̃_e with its slave displacement against the master's at the edge
/// node's projection. Other facets, and other points, use s_q as written above (T is the identity there).
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

/// The second derivative FrictionTerm::add_hessian() gives.
enum class FrictionHessian {
  /// ∇²j of the file comment (finite-difference checked).
  kExact,
  /// The primal-dual Newton model of Chan, Golub & Mulet (SIAM J. Sci. Comput. 20(6), 1999), made there for
  /// the same η_α in total-variation denoising. ∇²j bends along the slip only by w τ α²/r³: where a slip
  /// turns, Newton on it overshoots and its line search halves step after step. The model puts a dual
  /// variable z_q (|z_q| ≤ 1, the unit traction direction) in place of s/r, carried from one evaluation to
  /// the next by the linearisation of z r = s at the previous one (s⁻, r⁻, z⁻):
  ///   z = s⁻/r⁻ + (Δs − z⁻ (s⁻ᵀΔs)/r⁻)/r⁻,  Δs = s − s⁻,  scaled back to |z| ≤ 1,
  /// and gives  w τ Bᵀ P (I − ½(z sᵀ + s zᵀ)/r) P B / r:  symmetric, positive semidefinite (the rank-two term's
  /// eigenvalues are at most |z| |s|/r < 1), and ∇²j where z = s/r (the first evaluation, and in the limit of
  /// converging iterates, so Newton keeps its quadratic rate). The gradient stays exact: the minimiser is
  /// unchanged, only the Newton directions on the way to it.
  kPrimalDual,
};

class FrictionTerm : public EnergyTerm {
 public:
  /// `master` is null for an obstacle. `tau` and `alpha` have one value per point: τ_q ≥ 0, and α_q > 0
  /// wherever τ_q > 0 (a point with τ_q = 0 adds nothing).
  FrictionTerm(std::string name, const ContactSurface& slave, const ContactSurface* master,
               std::vector<ContactPoint> points, std::vector<double> tau, std::vector<double> alpha,
               const DofMap& dofs, const VectorXd& u_start);
  std::string name() const override { return name_; }
  double value(const VectorXd& u) const override;
  void add_gradient(const VectorXd& u, VectorXd& g) const override;
  void add_hessian(const VectorXd& u, MatrixSink& sink) const override;
  bool hessian_is_constant() const override { return false; }

  /// Slip increment s_q at every point (3 components, z = 0 in 2D); s̃_q at the nodal points of a Tri6
  /// surface (the file comment).
  std::vector<Eigen::Vector3d> slips(const VectorXd& u) const;
  const std::vector<ContactPoint>& points() const { return points_; }
  /// The regularisation length α_q of every point.
  const std::vector<double>& alphas() const { return alpha_; }
  /// The relative-displacement maps B of every point, before the projector: (dim · points) × num_dofs, rows
  /// dim·q … dim·q + dim − 1 the map of point q, so that s_q = P_q (B_q u − B_q u⁰) (the file comment).
  SparseMatrix slip_map(Index num_dofs) const;
  /// The bound w_q τ_q of every point's friction force.
  std::vector<double> bounds() const;
  /// New thresholds τ_q ≥ 0, one per point (α_q > 0 wherever τ_q > 0): the same points, slips and weights.
  /// The term's DOF support (support_of(), its Hessian blocks) is unchanged when the zero blocks are kept.
  void set_thresholds(const std::vector<double>& tau);
  /// Whether a point with τ_q = 0 adds a zero Hessian block (its DOFs stay in the support, for thresholds
  /// that set_thresholds() may make positive) or nothing (the default: the sparsest pattern).
  void keep_zero_blocks(bool keep) { keep_zero_blocks_ = keep; }
  /// Which second derivative add_hessian() gives (FrictionHessian; kExact by default). With kPrimalDual each
  /// evaluation at a new u moves the dual variables: the model depends on the sequence of points evaluated.
  void set_hessian_model(FrictionHessian model) { hessian_model_ = model; }

 private:
  struct Local {
    std::vector<Index> dofs;   ///< slave facet DOFs then master facet DOFs
    Eigen::MatrixXd B;         ///< dim × dofs: relative displacement = B u_loc
    Eigen::MatrixXd P;         ///< dim × dim tangential projector
    Eigen::VectorXd s0;        ///< P B u⁰_loc
    double wt = 0.0;           ///< w τ
    double alpha2 = 0.0;       ///< α_q²
  };
  /// The model's dual variable of one point (FrictionHessian::kPrimalDual): z, and the slip it was set at.
  struct Dual {
    Eigen::VectorXd z, s;
  };
  Eigen::VectorXd slip(const Local& l, const VectorXd& u) const;
  /// The D × D curvature of η_α at slip s of point q: ∇²η_α(s) × w τ, or its primal-dual model.
  Eigen::MatrixXd slip_curvature(std::size_t q, const Eigen::VectorXd& s) const;

  std::string name_;
  std::vector<ContactPoint> points_;
  std::vector<Local> local_;
  std::vector<double> alpha_;
  int dim_;
  bool keep_zero_blocks_ = false;
  FrictionHessian hessian_model_ = FrictionHessian::kExact;
  mutable std::vector<Dual> dual_;  ///< per point, empty until its first evaluation
};

}  // namespace symcontact
