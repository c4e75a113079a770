#include "symcontact/solvers/coulomb_thresholds.hpp"

#include <sstream>

#include "symcontact/contact/surface_tractions.hpp"

namespace symcontact {

namespace {

/// The budget of follow() in one solve (the header).
constexpr int kMaxFollows = 60, kStall = 10;

/// Nodal pressures (clamped at 0) on the friction-slave surface of pair p.
Eigen::VectorXd friction_side_pressure(const ContactSet& cs, int p, const DofMap& dofs, const VectorXd& u,
                                       const VectorXd& force) {
  // Along the interface normal, as the friction term and the contact results decompose (the normal of X
  // for a pair in ContactGeometry::kReference).
  const int f = cs.friction_family(p);
  const ContactSurface& s = cs.surfaces[cs.families()[f].slave];
  const VectorXd u_geometry = cs.geometry_displacement(p, u);
  const Eigen::MatrixXd xs = current_positions(s, dofs, u_geometry);
  const OppositeSide other = cs.opposite_side(f, dofs, u_geometry);
  const Eigen::MatrixXd normals =
      interface_normals(s, xs, other.master(), other.obstacle, cs.pairs[p].search_distance, cs.pairs[p].bisector_ray());
  return surface_tractions(s, dofs, u, force, &normals).pressure.cwiseMax(0.0);
}

/// The contact force F_c at the nodes where the multipliers act (Aᵀμ ≠ 0 on some DOF of the node: every
/// node's `dim` DOFs are consecutive), zero at the others. F_c is ∇E(u) on the free DOFs of the surfaces
/// (contact_forces.hpp); where no multiplier acts it is the solve's equilibrium error alone, and a pressure
/// read from it would be noise: with no contact anywhere (a surface not yet within its search distance, or
/// every gap open) the thresholds would be that noise, and their relative change O(1) at every iteration.
VectorXd active_contact_force(const ContactState& state, int dim) {
  VectorXd f = VectorXd::Zero(state.contact_force.size());
  for (Index d = 0; d + dim <= f.size(); d += dim)
    if (state.multiplier_force.segment(d, dim).cwiseAbs().maxCoeff() > 0.0)
      f.segment(d, dim) = state.contact_force.segment(d, dim);
  return f;
}

}  // namespace

CoulombThresholds::CoulombThresholds(const ContactSet& contacts, const DofMap& dofs, const VectorXd& u,
                                     const FrictionState* previous, double s_extrapolate, const Logger& log)
    : contacts_(contacts), dofs_(dofs), log_(log) {
  state_.u_start = u;
  if (previous) state_.previous_tau = previous->nodal_tau;
  const int np = static_cast<int>(contacts.pairs.size());
  state_.nodal_tau.assign(np, Eigen::VectorXd());
  for (int p = 0; p < np; ++p) {
    const ContactPair& pair = contacts.pairs[p];
    if (pair.friction == FrictionLaw::kNone) continue;
    any_friction_ = true;
    const ContactSurface& s = contacts.surfaces[contacts.families()[contacts.friction_family(p)].slave];
    Eigen::VectorXd& tau = state_.nodal_tau[p];
    tau = Eigen::VectorXd::Constant(s.num_nodes(), pair.friction == FrictionLaw::kTresca ? pair.tau : 0.0);
    if (pair.friction != FrictionLaw::kCoulomb) continue;
    any_coulomb_ = true;
    if (!previous || p >= static_cast<int>(previous->nodal_tau.size())) continue;
    const Eigen::VectorXd& last = previous->nodal_tau[p];
    if (last.size() != s.num_nodes() || !(last.maxCoeff() > 0.0)) continue;
    tau = last;
    warm_ = true;
    if (s_extrapolate > 0.0 && p < static_cast<int>(previous->previous_tau.size()) &&
        previous->previous_tau[p].size() == s.num_nodes())
      tau = (last + s_extrapolate * (last - previous->previous_tau[p])).cwiseMax(0.0);
  }
  // A first step starts from the run's unloaded start, whose thresholds are its cold ones (zero for Coulomb),
  // as the displacements are extrapolated from u = 0 there.
  if (!previous) state_.previous_tau = state_.nodal_tau;
}

std::string CoulombThresholds::advice() const {
  return "try smaller load steps ([contact_solver] max_step_cuts = 4, or more [steps]), or a larger friction "
         "regularisation alpha";
}

void CoulombThresholds::start_cold() {
  warm_ = false;
  for (std::size_t p = 0; p < contacts_.pairs.size(); ++p)
    if (contacts_.pairs[p].friction == FrictionLaw::kCoulomb) state_.nodal_tau[p].setZero();
}

std::vector<Eigen::VectorXd> CoulombThresholds::law_residual(const VectorXd& u, const VectorXd& force) const {
  const int np = static_cast<int>(contacts_.pairs.size());
  std::vector<Eigen::VectorXd> r(np);
  for (int p = 0; p < np; ++p)
    if (contacts_.pairs[p].friction == FrictionLaw::kCoulomb)
      r[p] = contacts_.pairs[p].mu * friction_side_pressure(contacts_, p, dofs_, u, force) - state_.nodal_tau[p];
  return r;
}

std::vector<Eigen::VectorXd> CoulombThresholds::residual(const VectorXd& u, const SolveReport& solve) const {
  const std::vector<Eigen::VectorXd> r = law_residual(u, active_contact_force(solve, dofs_.dim()));
  for (std::size_t p = 0; p < r.size(); ++p) {
    if (log_.level() < Verbosity::kDebug || r[p].size() == 0) continue;
    Index at = 0;
    r[p].cwiseAbs().maxCoeff(&at);
    const ContactSurface& s = contacts_.surfaces[contacts_.families()[contacts_.friction_family(p)].slave];
    std::ostringstream m;
    m << "    pair " << contacts_.pairs[p].name << ": largest threshold change at surface node " << at << " (X = "
      << s.X.col(at).transpose() << "): " << state_.nodal_tau[p][at] << " -> " << state_.nodal_tau[p][at] + r[p][at];
    log_.debug(m.str());
  }
  return r;
}

void CoulombThresholds::update(const std::vector<Eigen::VectorXd>& r, double omega) {
  for (std::size_t p = 0; p < r.size(); ++p)
    if (r[p].size() > 0) state_.nodal_tau[p] = (state_.nodal_tau[p] + omega * r[p]).cwiseMax(0.0);
}

void CoulombThresholds::follow_iterates(double tolerance) {
  if (!any_coulomb_) return;
  follow_tolerance_ = tolerance;
  state_.follower = this;
}

void CoulombThresholds::start_solve() { follow_ = FollowCount{}; }

bool CoulombThresholds::follow(const VectorXd& u, const VectorXd& force) {
  if (follow_.stopped) return false;
  const std::vector<Eigen::VectorXd> r = law_residual(u, force);
  const double change = relative_change(r, state_.nodal_tau);
  if (change <= follow_tolerance_) return false;
  if (follow_.changes == 0 || change < follow_.low) {
    follow_.low = change;
    follow_.since_low = 0;
  } else if (++follow_.since_low >= kStall) {
    follow_.stopped = true;
  }
  if (++follow_.changes > kMaxFollows) follow_.stopped = true;
  if (follow_.stopped) return false;
  update(r, 1.0);
  warm_ = true;
  return true;
}

}  // namespace symcontact
