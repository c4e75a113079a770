#include "symcontact/app/linear_solver_choice.hpp"

#include <algorithm>
#include <cstdio>
#include <utility>
#include <vector>

#include "symcontact/core/error.hpp"
#include "symcontact/solvers/condensation_cache.hpp"

namespace symcontact {

DistributedLimit distributed_path_limit(const ProblemSpec& spec) {
  const auto frictional = std::find_if(spec.contacts.begin(), spec.contacts.end(),
                                       [](const ContactSpec& c) { return c.friction != "none"; });
  if (frictional == spec.contacts.end()) return {};
  for (const BodySpec& b : spec.bodies)
    for (const MaterialSpec& m : b.materials)
      if (m.model != "linear_elastic")
        return {m.key + ".model", "the distributed path solves hyperelastic bodies without friction only, got \"" +
                                      m.model + "\" with " + frictional->key + ".friction = \"" +
                                      frictional->friction + "\""};
  return {};
}

namespace {

std::string gib(double bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f GiB", bytes / (1024.0 * 1024.0 * 1024.0));
  return text;
}

std::string figure(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2g", value);
  return text;
}

/// Where the cost part of the rule does not send a problem to the distributed path although that path solves
/// it: contact with a curved or meshed obstacle, where its interior point took twice the serial one's
/// iterations (a pad pressed onto a rigid sphere and dragged, docs/distributed.md), and between elastic
/// bodies (two spheres on two ranks: 14 times the serial solver's time). The first such contact's key and
/// what it is; "" when there is none.
std::string unmeasured_for_cost(const ProblemSpec& spec) {
  for (const ContactSpec& c : spec.contacts) {
    if (!c.obstacle) return c.key + " is between elastic bodies";
    if (c.obstacle->type != "plane") return c.key + "'s obstacle is not a plane";
  }
  return "";
}

/// The cost part of the rule: whether the dense work costs more, and the figures for the log.
struct DenseWork {
  bool dearer = false;
  std::string figures;
};

/// The serial solver's cost per interior-point iteration, in flops of a dense factorisation: |B|³/3 condensed;
/// with friction, where the condensation's cost rule takes the uncondensed problem instead (kDenseOverSparse,
/// solvers/condensation_cache.hpp), the sparse factorisation of K_ff at kSparseFlopInDenseFlops. The figures
/// say which.
std::pair<double, std::string> serial_work(const ProblemSpec& spec, const Model& model, double b,
                                           const std::vector<Index>& free_index, Index num_free) {
  const double dense = b * b * b / 3.0;
  const std::string condensed = "|B| = " + std::to_string(static_cast<Index>(b)) +
                                " condensed DOFs: a dense factorisation of " + figure(dense) + " flops";
  const bool friction =
      std::any_of(spec.contacts.begin(), spec.contacts.end(), [](const ContactSpec& c) { return c.friction != "none"; });
  if (!friction || !(dense > kSparseAboveFlops)) return {dense, condensed};  // K_ff's analysis only if it may matter
  const double flops = predict_factor(model.energy(), free_index, num_free).flops;
  if (!uncondensed_is_cheaper(dense, flops)) return {dense, condensed};
  const double sparse = kSparseFlopInDenseFlops * flops;
  return {sparse, condensed + ", uncondensed instead: a sparse factorisation of K_ff worth " + figure(sparse)};
}

/// A search that fails here fails again in the first step, which reports it: no estimate then.
DenseWork dense_work(const ProblemSpec& spec, const Model& model, const MemoryBudget& budget,
                     const std::vector<Index>& free_index, Index num_free) {
  double b = 0.0;
  try {
    b = static_cast<double>(predicted_condensed_dofs(spec, model));
  } catch (const EvaluationError& e) {
    return {false, std::string("no cost estimate: ") + e.what()};
  } catch (const SolveError& e) {
    return {false, std::string("no cost estimate: ") + e.what()};
  }
  const double iterative = budget.iterative_flops_per_dof * static_cast<double>(num_free);
  const auto [serial, figures] = serial_work(spec, model, b, free_index, num_free);
  return {serial > iterative,
          figures + " per interior-point iteration against " + figure(iterative) + " for the iterative path"};
}

}  // namespace

Index predicted_condensed_dofs(const ProblemSpec& spec, const Model& model) {
  const Index n = model.dofs().num_dofs();
  const int dim = model.dim();
  const ContactLinearization lin = model.contacts().linearize(model.dofs(), VectorXd::Zero(n));
  const bool friction =
      std::any_of(spec.contacts.begin(), spec.contacts.end(), [](const ContactSpec& c) { return c.friction != "none"; });
  std::vector<Index> free_index;
  model.fixed_dofs(0).free_numbering(n, free_index);
  std::vector<char> in_b(static_cast<std::size_t>(n), 0);
  for (int k = 0; k < lin.A.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(lin.A, k); it; ++it) {
      if (it.value() == 0.0) continue;
      const Index first = friction ? it.col() - it.col() % dim : it.col(), last = friction ? first + dim : first + 1;
      for (Index d = first; d < last; ++d) in_b[static_cast<std::size_t>(d)] = 1;
    }
  Index count = 0;
  for (Index d = 0; d < n; ++d) count += in_b[static_cast<std::size_t>(d)] && free_index[static_cast<std::size_t>(d)] >= 0;
  return count;
}

LinearSolverDecision choose_linear_solver(const ProblemSpec& spec, const Model& model, const MemoryBudget& budget) {
  if (spec.linear_solver == LinearSolverChoice::kDirect)
    return {false, DecisionBasis::kProblemFile, "linear solver: direct (as the problem file says)", {}};
  if (spec.linear_solver == LinearSolverChoice::kIterative)
    return {true, DecisionBasis::kProblemFile, "linear solver: iterative (as the problem file says)", {}};
  const double dofs = static_cast<double>(model.dofs().num_dofs());
  const std::string size = std::to_string(model.dofs().num_dofs()) + " DOFs";
  if (model.contacts().empty())
    return {false, DecisionBasis::kDefault, "linear solver: direct (automatic: no contact)", {}};
  const DistributedLimit limit = distributed_path_limit(spec);
  std::vector<Index> free_index;
  const Index num_free = model.fixed_dofs(0).free_numbering(model.dofs().num_dofs(), free_index);
  const std::string unmeasured = unmeasured_for_cost(spec);
  std::string cost = !limit.none() ? "no cost estimate: " + limit.key + " is not solved by the distributed path"
                                   : "no cost estimate: " + unmeasured;
  if (limit.none() && unmeasured.empty()) {
    const DenseWork work = dense_work(spec, model, budget, free_index, num_free);
    if (work.dearer)
      return {true, DecisionBasis::kDenseWork, "linear solver: iterative (automatic: " + work.figures + ")",
              work.figures};
    cost = work.figures;
  }
  if (dofs < budget.min_dofs)
    return {false, DecisionBasis::kDefault, "linear solver: direct (automatic: " + cost + "; " + size + ")", {}};
  const double nnz = predict_factor_nonzeros(model.energy(), free_index, num_free);
  double contact_nodes = 0.0;
  for (const ContactSurface& s : model.contacts().surfaces)
    if (!s.is_rigid()) contact_nodes += static_cast<double>(s.num_nodes());
  const double need = predicted_direct_peak_bytes(nnz, dofs, contact_nodes), available = budget.available_bytes;
  const std::string figures = "predicted peak " + gib(need) + ", " + gib(available) + " available";
  if (available < 0.0 || need <= kMemoryShare * available)
    return {false, DecisionBasis::kDefault, "linear solver: direct (automatic: " + cost + "; " + figures + ")", {}};
  if (!limit.none())
    return {false, DecisionBasis::kMemory,
            "linear solver: direct although it may not fit (automatic: " + figures + "; " + limit.key + ": " +
                limit.message + ")",
            figures};
  return {true, DecisionBasis::kMemory, "linear solver: iterative (automatic: " + figures + ")", figures};
}

std::string off_direct_reason(const LinearSolverDecision& d) {
  return (d.basis == DecisionBasis::kDenseWork ? "the direct solver's dense work is predicted to cost more ("
                                              : "the direct solver is predicted not to fit in memory (") +
         d.figures + ")";
}

LinearSolverDecision serial_only_choice(const ProblemSpec& spec, const Model& model, const MemoryBudget& budget) {
  LinearSolverDecision d = choose_linear_solver(spec, model, budget);
  if (!d.iterative) return d;
  if (d.basis == DecisionBasis::kDenseWork) {
    d.iterative = false;
    d.reason = "linear solver: direct, the only one here, where `symcontact run` would take the iterative path (" +
               d.figures + ")";
    return d;
  }
  const std::string why =
      d.basis == DecisionBasis::kMemory ? off_direct_reason(d) : "the problem file asks for \"iterative\"";
  throw InputError(spec.file, "contact_solver.linear_solver",
                   why + "; this program runs the direct solver only: run the problem with `symcontact run` or "
                         "`mpirun symcontact run`, which take the distributed path (docs/distributed.md)");
}

}  // namespace symcontact
