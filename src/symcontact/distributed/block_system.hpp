#pragma once
/// \file block_system.hpp
/// The model problem of the distributed path's tests and benchmark: a linear-elastic unit square (plane
/// strain) or unit cube on a structured simplex mesh of n divisions per side, E = 1, ν = 0.3, clamped at its
/// bottom (y = 0, resp. z = 0), its top moved by 0.01 along x, and a downward nodal load of 10⁻³ on every
/// node: the stiffness, the load, the fixed DOFs with their values, as solve_elasticity_gamg() takes them.
/// Part `part` of `parts` (an MPI rank of the ranks) assembles the stiffness of its contiguous range of
/// cells only, its share of K; the mesh, the load and the fixed DOFs are whole on every part.

#include <vector>

#include "symcontact/core/types.hpp"
#include "symcontact/mesh/mesh.hpp"

namespace symcontact {

struct BlockSystem {
  Mesh mesh;
  SparseMatrix K_lower;  ///< lower triangle of the part's share of the stiffness (dof = dim·node + comp)
  VectorXd f;
  std::vector<Index> fixed;
  VectorXd fixed_values;
};

BlockSystem clamped_block_system(int dim, int divisions, int part = 0, int parts = 1);

}  // namespace symcontact
