#pragma once
/// \file node_ordering.hpp
/// The node numbering of the distributed path's PETSc objects. Each rank owns a contiguous range of nodes
/// (petsc::my_rows); in the model's numbering (the mesh generator's) such a range is scattered over the whole
/// body — the second half of a Gmsh tetrahedral sphere's nodes touches nearly every node of the first, and a
/// split of its node list cuts 22 % of the mesh's edges. Numbered along a Hilbert curve through the reference
/// coordinates (mesh/hilbert_curve.hpp), each range is a compact region (8.6 % of the edges cut there): fewer
/// entries to exchange in every product and smoother aggregates for GAMG on each rank. The numbering depends on
/// the coordinates only, so it is the same on every rank and in every run.

#include <vector>

#include "symcontact/core/types.hpp"
#include "symcontact/distributed/contact_interior_point.hpp"

namespace symcontact {

class NodeOrdering {
 public:
  /// x: dim × nodes, the model's reference coordinates.
  explicit NodeOrdering(const Eigen::MatrixXd& x);

  Index num_nodes() const { return static_cast<Index>(position_.size()); }
  /// The PETSc number of model node k, and of model DOF d (dim·node + component).
  Index node(Index k) const { return position_[static_cast<std::size_t>(k)]; }
  Index dof(Index d) const { return dim_ * node(d / dim_) + d % dim_; }

  /// A vector over the DOFs, from the model's numbering to PETSc's and back.
  VectorXd to_petsc(const VectorXd& v) const;
  VectorXd to_model(const VectorXd& v) const;
  /// Columns per node (dim × nodes, such as coordinates) in PETSc's numbering.
  Eigen::MatrixXd nodes_to_petsc(const Eigen::MatrixXd& x) const;
  /// DOF indices in PETSc's numbering, in the same order.
  std::vector<Index> dofs_to_petsc(const std::vector<Index>& dofs) const;
  /// The constraints with their nodes and the columns of their rows and slip map in PETSc's numbering.
  NodalConstraints to_petsc(const NodalConstraints& c) const;

 private:
  SparseMatrix columns_to_petsc(const SparseMatrix& A) const;

  int dim_;
  std::vector<Index> position_;  ///< model node → PETSc node
};

}  // namespace symcontact
