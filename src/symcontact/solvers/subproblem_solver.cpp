#include "symcontact/solvers/subproblem_solver.hpp"

#include <algorithm>

#include "symcontact/contact/contact_set.hpp"
#include "symcontact/solvers/dual_subproblem.hpp"
#include "symcontact/solvers/primal_subproblem.hpp"

namespace symcontact {

bool independent_rows(const ContactSet& contacts) {
  return std::none_of(contacts.pairs.begin(), contacts.pairs.end(), [](const ContactPair& p) { return p.two_sided(); });
}

std::unique_ptr<DualIpopt> dual_method(SubproblemSolver choice, WarmStart warm) {
  if (choice == SubproblemSolver::kPrimalIpopt || choice == SubproblemSolver::kPrimalInteriorPoint) return nullptr;
  if (choice == SubproblemSolver::kDualInteriorPoint) return std::make_unique<DualInteriorPoint>(warm);
  return std::make_unique<DualIpopt>();
}

bool dense_primal_first(const ContactSet& contacts, SubproblemSolver choice) {
  const bool interior_point =
      choice == SubproblemSolver::kPrimalInteriorPoint || choice == SubproblemSolver::kDualInteriorPoint;
  return interior_point && independent_rows(contacts);
}

bool pairs_on_dense_primal(const ContactSet& contacts, int dim, SubproblemSolver choice) {
  const bool interior_point =
      choice == SubproblemSolver::kPrimalInteriorPoint || choice == SubproblemSolver::kDualInteriorPoint;
  return interior_point && !independent_rows(contacts) && dim == 2;
}

bool primal_interior_point_first(const ContactSet& contacts, int dim, SubproblemSolver choice) {
  return dense_primal_first(contacts, choice) || pairs_on_dense_primal(contacts, dim, choice);
}

std::unique_ptr<PrimalIpopt> primal_method(const ContactSet& contacts, int dim, SubproblemSolver choice,
                                           WarmStart warm) {
  if (dense_primal_first(contacts, choice)) return std::make_unique<PrimalInteriorPoint>(warm);
  if (pairs_on_dense_primal(contacts, dim, choice))
    return std::make_unique<PrimalInteriorPoint>(warm, PrimalForms::kCondensedOnly);
  return std::make_unique<PrimalIpopt>();
}

}  // namespace symcontact
