#include "symcontact/app/linear_solver_choice.hpp"

#include <cstdio>


namespace symcontact {

DistributedLimit distributed_path_limit(const ProblemSpec& spec) {
  for (const BodySpec& b : spec.bodies)
    for (const MaterialSpec& m : b.materials)
      if (m.model != "linear_elastic")
        return {m.key + ".model", "the distributed path solves linear-elastic bodies only, got \"" + m.model + "\""};
  for (const ContactSpec& c : spec.contacts) {
    if (c.friction != "none" && spec.order != 1)  // P2 surfaces' friction points mix nodes (friction_term.hpp)
      return {c.key + ".friction", "the distributed path solves friction on order-1 elements only, got \"" +
                                       c.friction + "\" with problem.order = " + std::to_string(spec.order)};
    if (!c.obstacle)  // docs/distributed.md: its Newton systems break down on examples/hertz_3d/two_spheres
      return {c.key + ".b", "the distributed path solves contact with rigid obstacles only, not between elastic "
                            "bodies (\"" + c.body_a + "\" and \"" + c.body_b + "\")"};
  }
  return {};
}

namespace {

std::string gib(double bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f GiB", bytes / (1024.0 * 1024.0 * 1024.0));
  return text;
}

}  // namespace

LinearSolverDecision choose_linear_solver(const ProblemSpec& spec, const Model& model, const MemoryBudget& budget) {
  if (spec.linear_solver == LinearSolverChoice::kDirect) return {false, "linear solver: direct (as the problem file says)"};
  if (spec.linear_solver == LinearSolverChoice::kIterative)
    return {true, "linear solver: iterative (as the problem file says)"};
  const double dofs = static_cast<double>(model.dofs().num_dofs());
  if (model.contacts().empty() || dofs < budget.min_dofs)
    return {false, "linear solver: direct (automatic: " + std::to_string(model.dofs().num_dofs()) + " DOFs)"};
  std::vector<Index> free_index;
  const Index num_free = model.fixed_dofs(0).free_numbering(model.dofs().num_dofs(), free_index);
  const double nnz = predict_factor_nonzeros(model.energy(), free_index, num_free);
  double contact_nodes = 0.0;
  for (const ContactSurface& s : model.contacts().surfaces)
    if (!s.is_rigid()) contact_nodes += static_cast<double>(s.num_nodes());
  const double need = predicted_direct_peak_bytes(nnz, dofs, contact_nodes), available = budget.available_bytes;
  const std::string figures = "predicted peak " + gib(need) + ", " + gib(available) + " available";
  if (available < 0.0 || need <= kMemoryShare * available) return {false, "linear solver: direct (automatic: " + figures + ")"};
  const DistributedLimit limit = distributed_path_limit(spec);
  if (!limit.none())
    return {false, "linear solver: direct although it may not fit (automatic: " + figures + "; " + limit.key + ": " +
                       limit.message + ")"};
  return {true, "linear solver: iterative (automatic: " + figures + ")"};
}

}  // namespace symcontact
