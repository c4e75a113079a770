#include "symcontact/solvers/condensation_cache.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "symcontact/core/error.hpp"
#include "symcontact/solvers/cholesky.hpp"
#include "symcontact/solvers/condensed_problem.hpp"
#include "symcontact/solvers/reduced_problem.hpp"
#include "symcontact/solvers/semidefinite_factor.hpp"
#include "symcontact/solvers/static_condensation.hpp"

namespace symcontact {

ContactWorkspace::ContactWorkspace() = default;
ContactWorkspace::~ContactWorkspace() = default;

namespace {

/// Widens the condensed set along each contact surface, so that a contact zone that grows over the geometry
/// iterations and load steps stays inside it (each refactorisation costs about one Cholesky floor): the
/// surface nodes holding condensed DOFs are grown by k rings of facet neighbours, k = max(2, ⌈n^{1/(d−1)}/4⌉)
/// for n such nodes (in 2D the zone's node count grows by about half, in 3D its radius by a quarter), and
/// the grown nodes' free DOFs of the components already condensed on that surface are added.
void add_condensation_margin(const ContactSet& contacts, const DofMap& dofs, const std::vector<Index>& free_index,
                             std::vector<char>& in_b) {
  for (const ContactSurface& s : contacts.surfaces) {
    if (s.is_rigid()) continue;
    const Index nn = s.num_nodes();
    std::vector<char> grown(nn, 0);
    std::vector<char> component(s.dim, 0);
    Index seeds = 0;
    for (Index k = 0; k < nn; ++k)
      for (int i = 0; i < s.dim; ++i) {
        const Index f = free_index[dofs.dof(s.body, s.nodes[k], i)];
        if (f >= 0 && in_b[f]) {
          if (!grown[k]) ++seeds;
          grown[k] = 1;
          component[i] = 1;
        }
      }
    if (seeds == 0) continue;
    const int rings = std::max(2, static_cast<int>(std::ceil(
                                      0.25 * std::pow(static_cast<double>(seeds), 1.0 / std::max(1, s.dim - 1)))));
    const int npf = s.nodes_per_facet();
    for (int r = 0; r < rings; ++r) {
      std::vector<char> next = grown;
      for (Index f = 0; f < s.num_facets(); ++f) {
        bool touches = false;
        for (int a = 0; a < npf && !touches; ++a) touches = grown[s.facet(f)[a]];
        if (touches)
          for (int a = 0; a < npf; ++a) next[s.facet(f)[a]] = 1;
      }
      grown.swap(next);
    }
    for (Index k = 0; k < nn; ++k) {
      if (!grown[k]) continue;
      for (int i = 0; i < s.dim; ++i) {
        const Index f = free_index[dofs.dof(s.body, s.nodes[k], i)];
        if (component[i] && f >= 0) in_b[f] = 1;
      }
    }
  }
}

/// The cost rule of the primal path: whether a sparse factorisation of K_ff plus the contact terms (the
/// uncondensed interior point, dense_primal_interior_point.hpp, or IPOPT's KKT system) costs less per iteration
/// than the dense |B| × |B| one of the condensed problem (kDenseOverSparse, kSparseAboveFlops). K_ff's analysis
/// is made once per model (ContactWorkspace::sparse_flops); the choice is logged at -v for each new |B|, as
/// `who` takes it.
bool sparse_is_cheaper(const SparseMatrix& K, Index b, const EnergyTerm& energy, const std::vector<Index>& free_index,
                       SparseAlternative who, ContactWorkspace& ws, const Logger& log) {
  if (ws.sparse_flops_energy != &energy || ws.sparse_flops_free_index != free_index) {
    CholeskySolver analysis;
    try {
      analysis.analyze(K);
    } catch (const SolveError&) {
      return false;
    }
    ws.sparse_flops = analysis.factor_flops();
    ws.sparse_flops_energy = &energy;
    ws.sparse_flops_free_index = free_index;
    ws.sparse_logged_for = -1;
  }
  const double dense = std::pow(static_cast<double>(b), 3) / 3.0;
  const bool sparse = uncondensed_is_cheaper(
      dense, ws.sparse_flops, who == SparseAlternative::kOptimiser ? kOptimiserSparseAboveFlops : kSparseAboveFlops);
  if (ws.sparse_logged_for != b) {
    ws.sparse_logged_for = b;
    std::ostringstream m;
    const char* choice = !sparse ? "condensed"
                         : who == SparseAlternative::kWholeSolve
                             ? "not condensed"
                             : "condensed, IPOPT's primal solves on the uncondensed problem";
    m << "  contact subproblems " << choice << " (|B| = " << b
      << ": a dense factorisation of " << std::setprecision(2) << dense << " flops per interior-point iteration against "
      << ws.sparse_flops << " for the sparse one of K_ff)";
    log.detail(m.str());
  }
  return sparse;
}

}  // namespace

std::unique_ptr<CondensedProblem> condense_problem(ReducedProblem& bulk, const ReducedProblem& problem,
                                                   const ContactSet& contacts, const DofMap& dofs,
                                                   const std::vector<std::shared_ptr<const FrictionTerm>>& friction,
                                                   const VectorXd& u, const VectorXd& x, const EnergyTerm& energy,
                                                   ContactWorkspace& ws, const CondensationLimits& limits,
                                                   const Logger& log, std::shared_ptr<const CondensedLoad>& load) {
  const Index n = problem.num_free();
  const auto& free_index = problem.free_index();
  // B: the free DOFs of the constraint rows and of the friction terms.
  std::vector<char> in_b(n, 0);
  const SparseMatrix& A = problem.constraint_matrix();
  for (int j = 0; j < A.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(A, j); it; ++it)
      if (it.value() != 0.0) in_b[j] = 1;
  std::vector<std::shared_ptr<const EnergyTerm>> extras;
  for (const auto& t : friction) {
    if (!t) continue;
    extras.push_back(t);
    for (Index d : support_of(*t, u))
      if (free_index[d] >= 0) in_b[free_index[d]] = 1;
  }
  const bool same_model = ws.condensation && !ws.condensation->empty() && ws.energy == &energy &&
                          ws.free_index == free_index;
  bool covered = same_model;
  if (same_model) {
    const auto& pos = ws.condensation->boundary_position();
    for (Index k = 0; k < n && covered; ++k)
      if (in_b[k] && pos[k] < 0) covered = false;
  }
  if (!covered) {
    if (same_model)  // grow: keep what was condensed before, so that a zone moving back and forth settles
      for (Index k : ws.condensation->boundary()) in_b[k] = 1;
    add_condensation_margin(contacts, dofs, free_index, in_b);
    std::vector<Index> boundary;
    for (Index k = 0; k < n; ++k)
      if (in_b[k]) boundary.push_back(k);
    if (boundary.empty() || static_cast<Index>(boundary.size()) > limits.max_condensed_dofs ||
        2 * static_cast<Index>(boundary.size()) > n)
      return nullptr;
    SparseMatrix K;
    bulk.hessian_lower(VectorXd::Zero(n), K);
    const Index nb = static_cast<Index>(boundary.size());
    const SparseAlternative who = limits.sparse_alternative;
    if (who == SparseAlternative::kWholeSolve && !extras.empty() &&
        sparse_is_cheaper(K, nb, energy, free_index, who, ws, log))
      return nullptr;
    ws.optimise_uncondensed =
        who == SparseAlternative::kOptimiserAlways ||
        (who == SparseAlternative::kOptimiser && sparse_is_cheaper(K, nb, energy, free_index, who, ws, log));
    if (who == SparseAlternative::kOptimiserAlways)
      log.detail("  contact subproblems condensed (|B| = " + std::to_string(nb) +
                 "), IPOPT's primal solves on the uncondensed problem (ipopt_problem = \"uncondensed\")");
    if (!ws.condensation) ws.condensation = std::make_unique<StaticCondensation>();
    try {
      ws.condensation->compute(K, std::move(boundary));
    } catch (const SolveError& e) {
      log.detail(std::string("  static condensation not used: ") + e.what());
      ws.energy = nullptr;
      ws.condensation.reset();
      return nullptr;
    }
    ws.energy = &energy;
    ws.free_index = free_index;
    ++ws.factorisations;
    load.reset();
    log.debug("  static condensation onto " + std::to_string(ws.condensation->boundary().size()) + " of " +
              std::to_string(n) + " free DOFs");
  }
  if (!load && limits.same_loads && ws.load && ws.load_of == ws.factorisations && ws.load->r0.size() == n) {
    load = ws.load;  // the caller vouches for r₀ (CondensationLimits::same_loads)
  }
  if (!load) {
    // The load part (one interior solve) depends on the loads and Dirichlet values only, through r₀ = ∇E(0):
    // the Coulomb iterations of a load step share it.
    VectorXd r0;
    bulk.gradient(VectorXd::Zero(n), r0);
    if (ws.load && ws.load_of == ws.factorisations && ws.load->r0.size() == n && ws.load->r0 == r0) {
      load = ws.load;
    } else {
      load = std::make_shared<const CondensedLoad>(condense_load(bulk, *ws.condensation));
      ws.load = load;
      ws.load_of = ws.factorisations;
    }
  }
  return std::make_unique<CondensedProblem>(bulk, *ws.condensation, load, std::move(extras), A,
                                            problem.constraint_offset(), x);
}

bool surfaces_condensed(const ContactSet& contacts, const DofMap& dofs, const std::vector<Index>& free_index,
                        const std::vector<Index>& b_position) {
  for (const ContactSurface& s : contacts.surfaces) {
    if (s.is_rigid()) continue;
    for (Index node : s.nodes)
      for (int i = 0; i < s.dim; ++i) {
        const Index f = free_index[dofs.dof(s.body, node, i)];
        if (f >= 0 && b_position[f] < 0) return false;
      }
  }
  return true;
}

const SemidefiniteFactor* dual_schur_factor(ContactWorkspace& ws, const Logger& log) {
  // Pivots below this fraction of max diag(S) are rigid motions: theirs are round-off (1e-16 relative),
  // the softest deformation seen from the contact DOFs of a body is far above it.
  constexpr double kRankTolerance = 1e-10;
  constexpr double kNullResidual = 1e-8;
  if (!ws.condensation || ws.condensation->empty()) return nullptr;
  if (ws.schur_factor_of != ws.factorisations) {
    ws.schur_factor.reset();
    ws.schur_factor_of = ws.factorisations;
    try {
      auto f = std::make_unique<SemidefiniteFactor>(ws.condensation->schur_lower(), kRankTolerance);
      std::ostringstream s;
      s << "  dual solve: Schur complement of rank " << f->rank() << " of " << f->size() << " ("
        << f->size() - f->rank() << " rigid motion(s), null residual " << f->null_residual() << ")";
      if (f->null_residual() <= kNullResidual) {
        ws.schur_factor = std::move(f);
      } else {
        s << ": not clean, the primal is solved instead";
      }
      log.debug(s.str());
    } catch (const SolveError& e) {
      log.debug(std::string("  dual solve not used: ") + e.what());
    }
  }
  return ws.schur_factor.get();
}

void complete_interior(const EnergyTerm& energy, const FixedDofs& fixed, VectorXd& u, ContactWorkspace& workspace) {
  if (!workspace.interior_pending) return;
  workspace.interior_pending = false;
  if (!workspace.condensation || !workspace.load)
    throw std::logic_error("complete_interior: the workspace holds no condensation to complete u with");
  const ReducedProblem bulk(energy, fixed, u.size());
  const VectorXd y = boundary_values(*workspace.condensation, bulk.restrict(u));
  u = bulk.expand(expand_condensed(*workspace.condensation, *workspace.load, y));
}

}  // namespace symcontact
