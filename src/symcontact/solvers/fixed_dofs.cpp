#include "symcontact/solvers/fixed_dofs.hpp"

namespace symcontact {

void FixedDofs::fix(Index dof, double value, int owner) {
  dofs.push_back(dof);
  values.push_back(value);
  owners.push_back(owner);
}

std::vector<int> FixedDofs::owner_of(Index num_dofs) const {
  std::vector<int> o(num_dofs, -1);
  for (std::size_t k = 0; k < dofs.size(); ++k) o[dofs[k]] = owners[k];
  return o;
}

Index FixedDofs::free_numbering(Index num_dofs, std::vector<Index>& free_index) const {
  free_index.assign(num_dofs, 0);
  for (Index d : dofs) free_index[d] = -1;
  Index k = 0;
  for (Index d = 0; d < num_dofs; ++d)
    if (free_index[d] == 0) free_index[d] = k++;
    else free_index[d] = -1;
  return k;
}

void FixedDofs::impose(VectorXd& u) const {
  for (std::size_t k = 0; k < dofs.size(); ++k) u[dofs[k]] = values[k];
}

}  // namespace symcontact
