#include "symcontact/fem/dof_map.hpp"

namespace symcontact {

int DofMap::add_body(Index num_nodes) {
  offsets_.push_back(total_);
  num_nodes_.push_back(num_nodes);
  total_ += dim_ * num_nodes;
  return num_bodies() - 1;
}

}  // namespace symcontact
