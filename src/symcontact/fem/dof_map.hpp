#pragma once
/// \file dof_map.hpp
/// Global numbering of the displacement DOFs of several bodies. Body b owns the contiguous range
/// [offset(b), offset(b) + dim·num_nodes(b)); inside it DOFs are node-major:
/// dof(b, node, comp) = offset(b) + dim·node + comp.

#include <vector>

#include "symcontact/core/types.hpp"

namespace symcontact {

class DofMap {
 public:
  DofMap() = default;
  explicit DofMap(int dim) : dim_(dim) {}
  /// Appends a body with `num_nodes` nodes; returns its index.
  int add_body(Index num_nodes);
  int dim() const { return dim_; }
  int num_bodies() const { return static_cast<int>(offsets_.size()); }
  Index offset(int body) const { return offsets_[body]; }
  Index num_body_dofs(int body) const { return dim_ * num_nodes_[body]; }
  Index num_dofs() const { return total_; }
  Index dof(int body, Index node, int comp) const { return offsets_[body] + dim_ * node + comp; }

 private:
  int dim_ = 2;
  std::vector<Index> offsets_, num_nodes_;
  Index total_ = 0;
};

}  // namespace symcontact
