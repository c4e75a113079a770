#pragma once
/// \file block_system.hpp
/// The model problems of the distributed path's tests and benchmark, on a linear-elastic unit square (plane
/// strain) or unit cube, structured simplex mesh of n divisions per side, E = 1, ν = 0.3:
///
/// - clamped_block_system: clamped at its bottom (y = 0, resp. z = 0), its top moved by 0.01 along x, a
///   downward nodal load of 10⁻³ on every node;
/// - block_on_ball_system: its top moved down by `depth` (every component fixed), no load, pressed onto a
///   rigid ball (2D: disc) of radius R whose top touches the centre of the block's bottom face — a Hertz
///   contact when the contact zone is small against the block. One constraint per bottom node along the
///   vertical: u_z ≥ l = −(R − √(R² − r²)), r the node's distance from the centre of the bottom face (the
///   small-displacement gap along the vertical; R must exceed the half-diagonal of the face).
///
/// Part `part` of `parts` (an MPI rank of the ranks) assembles the stiffness of its contiguous range of
/// cells only, its share of K; the mesh, the load, the fixed DOFs and the constraints are whole on every part.

#include <vector>

#include "symcontact/core/types.hpp"
#include "symcontact/distributed/contact_interior_point.hpp"
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

struct ObstacleSystem {
  BlockSystem block;
  NodalConstraints contact;
};

ObstacleSystem block_on_ball_system(int dim, int divisions, double radius, double depth, int part = 0,
                                    int parts = 1);

}  // namespace symcontact
