#pragma once
/// \file fixed_dofs.hpp
/// Dirichlet conditions in global DOF numbering: u[dofs[k]] = values[k]. A DOF named twice keeps the
/// last value given (conditions are applied in problem-file order), and belongs to that condition
/// (`owners[k]`, an index chosen by the caller) for reaction forces.

#include <vector>

#include "symcontact/core/types.hpp"

namespace symcontact {

struct FixedDofs {
  std::vector<Index> dofs;
  std::vector<double> values;
  std::vector<int> owners;

  void fix(Index dof, double value, int owner = -1);
  /// owner_of[d] = the owner of the condition that holds DOF d (the last one given), or −1 if free.
  std::vector<int> owner_of(Index num_dofs) const;
  /// free_index[d] = position of d among the free DOFs (in increasing order), or −1 if fixed.
  /// Returns the number of free DOFs.
  Index free_numbering(Index num_dofs, std::vector<Index>& free_index) const;
  /// Writes the fixed values into u.
  void impose(VectorXd& u) const;
};

}  // namespace symcontact
