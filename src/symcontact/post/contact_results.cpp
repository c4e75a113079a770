#include "symcontact/post/contact_results.hpp"

#include <cmath>
#include <limits>

#include "symcontact/contact/contact_surface.hpp"
#include "symcontact/fem/shape_functions.hpp"

namespace symcontact {

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Displacement of `surface` at point (facet, eta), 3 components (zero for a rigid surface).
Eigen::Vector3d displacement_at(const ContactSurface& surface, Index facet, const double* eta, const DofMap& dofs,
                                const VectorXd& u) {
  Eigen::Vector3d w = Eigen::Vector3d::Zero();
  if (surface.is_rigid()) return w;
  double M[10];
  shape_functions(surface.facet_type, eta, M, nullptr);
  for (int b = 0; b < surface.nodes_per_facet(); ++b)
    for (int c = 0; c < surface.dim; ++c)
      w[c] += M[b] * u[dofs.dof(surface.body, surface.nodes[surface.facet(facet)[b]], c)];
  return w;
}

/// Whether p, projecting past an end of the master, lies on the normal through that end up to round-off (a
/// node where both faces end: the two ends coincide, and which side of the end the node falls on is the
/// round-off of its displacement, which would make its gap a number in one run and NaN in another). Then cp
/// is the projection onto the end. The slack: 1e-9 of the search distance.
bool at_opposite_end(const MasterGeometry& mg, const Eigen::VectorXd& p, const Eigen::Vector3d& normal, double search,
                     ContactPoint& cp) {
  constexpr double kSlack = 1e-9;
  ContactPoint end;
  if (!project_to_master(mg, p, normal, search, end, true)) return false;
  const Eigen::Vector3d off = end.x - end.xbar - end.gap * end.normal;  // p − x̄ across the normal
  if (off.norm() > kSlack * search) return false;
  cp = end;
  return true;
}

/// Signed distance of every node of side `side` to the opposite side of its pair, and the interface normal
/// there (interface_normal(), contact_points.hpp: outward for this side); nodes that project onto nothing
/// get a NaN gap and keep their own normal. xs and the opposite side are at X + u_geometry. With
/// `linearised_at` (a pair in ContactGeometry::kReference, u_geometry = 0) the gap is the solver's
/// linearised one, θ(X) + d·(u_s − u_m(η̄)) at the node with the projection η̄ and direction d of X.
Eigen::VectorXd nodal_gaps(const ContactSet& cs, const ContactPair& pair, int side, const DofMap& dofs,
                           const VectorXd& u_geometry, const Eigen::MatrixXd& xs, Eigen::MatrixXd& normals,
                           const VectorXd* linearised_at) {
  const ContactSurface& s = cs.surfaces[side == 0 ? pair.surface_a : pair.surface_b];
  Eigen::VectorXd gap = Eigen::VectorXd::Constant(s.num_nodes(), kNaN);
  const Eigen::MatrixXd own = normals;
  auto node_displacement = [&](Index k) {
    Eigen::Vector3d w = Eigen::Vector3d::Zero();
    if (!s.is_rigid())
      for (int c = 0; c < s.dim; ++c) w[c] = (*linearised_at)[dofs.dof(s.body, s.nodes[k], c)];
    return w;
  };
  if (pair.obstacle >= 0) {
    for (Index k = 0; k < s.num_nodes(); ++k) {
      Eigen::Vector3d p = Eigen::Vector3d::Zero(), xbar, n;
      p.head(s.dim) = xs.col(k);
      cs.obstacles[pair.obstacle].project(p, xbar, n);
      gap[k] = (p - xbar).dot(n);
      if (linearised_at) gap[k] += n.dot(node_displacement(k));
      normals.col(k) = -n.head(s.dim);
    }
    return gap;
  }
  const ContactSurface& other = cs.surfaces[side == 0 ? pair.surface_b : pair.surface_a];
  const MasterGeometry mg = prepare_master(other, current_positions(other, dofs, u_geometry));
  for (Index k = 0; k < s.num_nodes(); ++k) {
    Eigen::Vector3d n3 = Eigen::Vector3d::Zero();
    n3.head(s.dim) = own.col(k);
    ContactPoint cp;
    if (project_to_master(mg, xs.col(k), n3, pair.search_distance, cp, false, pair.bisector_ray() ? &n3 : nullptr) ||
        at_opposite_end(mg, xs.col(k), n3, pair.search_distance, cp)) {
      gap[k] = cp.gap;
      if (linearised_at)
        gap[k] += cp.row_direction().dot(node_displacement(k) -
                                         displacement_at(other, cp.master_facet, cp.eta, dofs, *linearised_at));
      // With the bisector ray, cp.normal is already the interface normal (the master side's).
      normals.col(k) = interface_normal(own.col(k), cp.normal.head(s.dim), pair.two_sided() && !pair.bisector_ray());
    }
  }
  return gap;
}

/// Weak nodal average of the point slips of a friction term over its slave surface.
/// Values v (rows × points) given at the points of a friction term, as nodal values (rows × nodes): the
/// weighted average Σ_q w_q N_k(ξ_q) v_q / Σ_q w_q N_k(ξ_q) (the point's own value at a nodal point); NaN
/// at nodes no point reaches.
Eigen::MatrixXd point_values_at_nodes(const ContactSurface& s, const FrictionTerm& term, const Eigen::MatrixXd& v) {
  Eigen::MatrixXd num = Eigen::MatrixXd::Zero(v.rows(), s.num_nodes());
  Eigen::VectorXd den = Eigen::VectorXd::Zero(s.num_nodes());
  double N[10];
  for (std::size_t q = 0; q < term.points().size(); ++q) {
    const ContactPoint& p = term.points()[q];
    shape_functions(s.facet_type, p.xi, N, nullptr);
    for (int a = 0; a < s.nodes_per_facet(); ++a) {
      const Index k = s.facet(p.slave_facet)[a];
      num.col(k) += p.weight * N[a] * v.col(static_cast<Index>(q));
      den[k] += p.weight * N[a];
    }
  }
  Eigen::MatrixXd out = Eigen::MatrixXd::Constant(v.rows(), s.num_nodes(), kNaN);
  for (Index k = 0; k < s.num_nodes(); ++k)
    if (den[k] > 0) out.col(k) = num.col(k) / den[k];
  return out;
}

Eigen::MatrixXd nodal_slips(const ContactSurface& s, const FrictionTerm& term, const VectorXd& u) {
  const std::vector<Eigen::Vector3d> sq = term.slips(u);
  Eigen::MatrixXd v(s.dim, static_cast<Index>(sq.size()));
  for (std::size_t q = 0; q < sq.size(); ++q) v.col(static_cast<Index>(q)) = sq[q].head(s.dim);
  return point_values_at_nodes(s, term, v);
}

/// The regularisation length α at every node of the term's slave surface (NaN where no point reaches).
Eigen::VectorXd nodal_alphas(const ContactSurface& s, const FrictionTerm& term) {
  const Eigen::Map<const Eigen::RowVectorXd> a(term.alphas().data(), static_cast<Index>(term.alphas().size()));
  return point_values_at_nodes(s, term, a).row(0).transpose();
}

/// The force of pair `pi` alone on every DOF, split as the solve builds it: its constraint rows' Aᵀμ (the
/// normal part, plus the solve's equilibrium defect where only this pair's rows reach) and its friction
/// term's −∇j (the tangential part), and ∫ λ dΓ = Σ_r μ_r Σ_q w_q φ_r.
struct PairForce {
  VectorXd normal, defect, tangential;  ///< Aᵀμ_p, the defect at the DOFs the pair alone reaches, −∇j_p
  double normal_load = 0.0;
};

/// Per DOF, the pair whose constraint rows alone touch it; −1 for none, −2 for several.
std::vector<int> dof_owners(const ContactSet& cs, const ContactLinearization& lin, Index num_dofs) {
  std::vector<int> owner(num_dofs, -1);
  if (lin.A.cols() != num_dofs || static_cast<Index>(lin.row_family.size()) != lin.A.rows()) return owner;
  for (Index c = 0; c < lin.A.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(lin.A, c); it; ++it) {
      const int p = cs.families()[lin.row_family[it.row()]].pair;
      int& o = owner[it.col()];
      o = o == -1 || o == p ? p : -2;
    }
  return owner;
}

PairForce pair_force(const ContactSet& cs, const VectorXd& u, const ContactState& state,
                     const std::vector<int>& owner, int pi) {
  const ContactLinearization& lin = state.linearization;
  PairForce f;
  f.normal = VectorXd::Zero(u.size());
  f.defect = VectorXd::Zero(u.size());
  f.tangential = VectorXd::Zero(u.size());
  if (state.multipliers.size() == lin.A.rows() && lin.A.cols() == u.size()) {
    VectorXd mu = VectorXd::Zero(state.multipliers.size());
    for (Index r = 0; r < mu.size(); ++r)
      if (cs.families()[lin.row_family[r]].pair == pi) {
        mu[r] = state.multipliers[r];
        f.normal_load += mu[r] * lin.row_support[r];
      }
    f.normal = lin.A.transpose() * mu;
  }
  // The solve's equilibrium defect goes to the normal part of the pair that alone touches the DOF.
  if (state.force_defect.size() == u.size())
    for (Index d = 0; d < u.size(); ++d)
      if (owner[d] == pi) f.defect[d] = state.force_defect[d];
  if (pi < static_cast<int>(state.friction.size()) && state.friction[pi]) {
    state.friction[pi]->add_gradient(u, f.tangential);
    f.tangential = -f.tangential;
  }
  return f;
}

/// The dim × n nodal values of a DOF vector on surface s (zero for a rigid surface).
Eigen::MatrixXd nodal_values(const ContactSurface& s, const DofMap& dofs, const VectorXd& v) {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(s.dim, s.num_nodes());
  if (!s.is_rigid())
    for (Index k = 0; k < s.num_nodes(); ++k)
      for (int i = 0; i < s.dim; ++i) out(i, k) = v[dofs.dof(s.body, s.nodes[k], i)];
  return out;
}

/// In 2D, ±|v_k| with the sign of v_k·τ_k, τ_k = (−ν_y, ν_x) (the header); NaN where v_k is.
Eigen::VectorXd signed_along_tangent(const Eigen::MatrixXd& v, const Eigen::MatrixXd& normals) {
  Eigen::VectorXd out(v.cols());
  for (Index k = 0; k < v.cols(); ++k) {
    const double along = -v(0, k) * normals(1, k) + v(1, k) * normals(0, k);
    const double norm = v.col(k).norm();
    out[k] = along < 0 ? -norm : norm;
  }
  return out;
}

/// One side of pair `pi` on surface `si`: forces from the pair's own rows and friction term, pressure and
/// traction per lumped reference area (in the test basis, surface_tractions.hpp), gaps, slips.
/// `multiplier_pressure`: the pressure of Aᵀμ_p alone (for the status: exactly zero where no active row reaches).
/// The friction term of pair pi if surface si is its slave side (the side its slips are measured on), else null.
const FrictionTerm* friction_on_side(const ContactSet& cs, const ContactState& state, int pi, int si) {
  const bool has_friction = pi < static_cast<int>(state.friction.size()) && state.friction[pi];
  return has_friction && si == cs.families()[cs.friction_family(pi)].slave ? state.friction[pi].get() : nullptr;
}

ContactSideResult side_result(const ContactSet& cs, int pi, int side, const DofMap& dofs, const VectorXd& u,
                              const PairForce& pf, const ContactState& state,
                              Eigen::VectorXd& multiplier_pressure) {
  const ContactPair& pair = cs.pairs[pi];
  const int si = side == 0 ? pair.surface_a : pair.surface_b;
  const ContactSurface& s = cs.surfaces[si];
  ContactSideResult sr;
  sr.surface = si;
  sr.x = current_positions(s, dofs, u);
  sr.X = s.X;
  // The normals (and gaps) the solver used: those of X for a pair in ContactGeometry::kReference.
  const bool reference = pair.geometry == ContactGeometry::kReference;
  Eigen::MatrixXd normals = nodal_normals(s, reference ? s.X : sr.x);
  sr.gap = nodal_gaps(cs, pair, side, dofs, cs.geometry_displacement(pi, u), reference ? s.X : sr.x, normals,
                      reference ? &u : nullptr);
  sr.normals = normals;
  const Eigen::MatrixXd multiplier_part = nodal_values(s, dofs, pf.normal);
  sr.normal_part = multiplier_part + nodal_values(s, dofs, pf.defect);
  const Eigen::MatrixXd tangential_part = nodal_values(s, dofs, pf.tangential);
  sr.force = sr.normal_part + tangential_part;
  sr.normal_force = sr.normal_part.rowwise().sum();
  sr.tangential_force = tangential_part.rowwise().sum();
  sr.total_force = sr.force.rowwise().sum();
  const Eigen::MatrixXd fn = test_basis_forces(s, sr.normal_part), ft = test_basis_forces(s, tangential_part),
                        fm = test_basis_forces(s, multiplier_part);
  multiplier_pressure = Eigen::VectorXd::Zero(s.num_nodes());
  const Eigen::VectorXd current_area = lumped_areas(s, sr.x);
  sr.pressure = Eigen::VectorXd::Zero(s.num_nodes());
  sr.current_pressure = Eigen::VectorXd::Zero(s.num_nodes());
  sr.tangential = Eigen::MatrixXd::Zero(s.dim, s.num_nodes());
  for (Index k = 0; k < s.num_nodes(); ++k) {
    if (s.nodal_area[k] <= 0) continue;
    sr.pressure[k] = -fn.col(k).dot(normals.col(k)) / s.nodal_area[k];
    multiplier_pressure[k] = -fm.col(k).dot(normals.col(k)) / s.nodal_area[k];
    sr.tangential.col(k) = ft.col(k) / s.nodal_area[k];
    if (current_area[k] > 0) sr.current_pressure[k] = sr.pressure[k] * s.nodal_area[k] / current_area[k];
  }
  const FrictionTerm* friction = friction_on_side(cs, state, pi, si);
  sr.slip = friction ? nodal_slips(s, *friction, u) : Eigen::MatrixXd::Constant(s.dim, s.num_nodes(), kNaN);
  sr.displacement = nodal_values(s, dofs, u);
  if (s.dim == 2) {
    sr.tangential_along = signed_along_tangent(sr.tangential, normals);
    sr.slip_along = signed_along_tangent(sr.slip, normals);
  }
  return sr;
}

/// Status from the law (see the header): open / contact (stick) / slip. `alpha`: the regularisation length
/// at every node (NaN off the friction side, whose slips are NaN too).
void set_status(ContactSideResult& sr, const Eigen::VectorXd& multiplier_pressure, double max_pressure,
                const Eigen::VectorXd& alpha) {
  sr.status = Eigen::VectorXi::Zero(sr.pressure.size());
  if (!(max_pressure > 0)) return;
  for (Index k = 0; k < sr.status.size(); ++k) {
    if (!(multiplier_pressure[k] > kContactPressureFraction * max_pressure)) continue;
    sr.status[k] = 1;
    const double s = sr.slip.col(k).norm();
    if (std::isfinite(s) && s >= kSlipRatio * std::sqrt(s * s + alpha[k] * alpha[k])) sr.status[k] = 2;
  }
}

}  // namespace

std::vector<ContactPairResult> contact_results(const ContactSet& cs, const DofMap& dofs, const VectorXd& u,
                                               const ContactState& state) {
  std::vector<ContactPairResult> out;
  const std::vector<int> owner = dof_owners(cs, state.linearization, u.size());
  for (int pi = 0; pi < static_cast<int>(cs.pairs.size()); ++pi) {
    const ContactPair& pair = cs.pairs[pi];
    ContactPairResult r;
    r.name = pair.name;
    const PairForce pf = pair_force(cs, u, state, owner, pi);
    r.normal_load = pf.normal_load;
    // One side for an obstacle and for self-contact (the surface is both sides), two otherwise.
    const int nsides = pair.obstacle >= 0 || pair.surface_a == pair.surface_b ? 1 : 2;
    std::vector<Eigen::VectorXd> multiplier_pressure(nsides);
    double max_multiplier_pressure = 0.0;
    for (int side = 0; side < nsides; ++side) {
      r.sides.push_back(side_result(cs, pi, side, dofs, u, pf, state, multiplier_pressure[side]));
      r.max_pressure = std::max(r.max_pressure, r.sides.back().pressure.maxCoeff());
      max_multiplier_pressure = std::max(max_multiplier_pressure, multiplier_pressure[side].maxCoeff());
    }
    // Round-off at nodes no active row reaches (|p| ~ 1e-16 max p) is reported as 0; anything larger
    // — an adhesive pressure, which would be a bug — is left visible.
    for (int side = 0; side < nsides; ++side) {
      ContactSideResult& sr = r.sides[side];
      for (Index k = 0; k < sr.pressure.size(); ++k)
        if (std::abs(sr.pressure[k]) <= 1e-12 * r.max_pressure) sr.pressure[k] = sr.current_pressure[k] = 0.0;
      const ContactSurface& s = cs.surfaces[sr.surface];
      const FrictionTerm* friction = friction_on_side(cs, state, pi, sr.surface);
      set_status(sr, multiplier_pressure[side], max_multiplier_pressure,
                 friction ? nodal_alphas(s, *friction) : Eigen::VectorXd::Constant(s.num_nodes(), kNaN));
    }
    r.total_force = r.sides[0].total_force;
    r.normal_force = r.sides[0].normal_force;
    r.tangential_force = r.sides[0].tangential_force;
    const ContactSurface& sa = cs.surfaces[pair.surface_a];
    for (Index k = 0; k < sa.num_nodes(); ++k)
      if (r.sides[0].status[k]) r.contact_measure += sa.nodal_area[k];
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace symcontact
