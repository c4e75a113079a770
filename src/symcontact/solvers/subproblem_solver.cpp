#include "symcontact/solvers/subproblem_solver.hpp"

namespace symcontact {

namespace {
constexpr SubproblemSolver kAll[] = {SubproblemSolver::kPrimalIpopt, SubproblemSolver::kDualIpopt,
                                     SubproblemSolver::kDualInteriorPoint, SubproblemSolver::kPrimalInteriorPoint};
}  // namespace

const char* subproblem_solver_name(SubproblemSolver s) {
  switch (s) {
    case SubproblemSolver::kPrimalIpopt:
      return "primal_ipopt";
    case SubproblemSolver::kDualIpopt:
      return "dual_ipopt";
    case SubproblemSolver::kDualInteriorPoint:
      return "dual_interior_point";
    case SubproblemSolver::kPrimalInteriorPoint:
      return "primal_interior_point";
  }
  return "";
}

std::optional<SubproblemSolver> parse_subproblem_solver(const std::string& name) {
  for (const SubproblemSolver s : kAll)
    if (name == subproblem_solver_name(s)) return s;
  return std::nullopt;
}

}  // namespace symcontact
