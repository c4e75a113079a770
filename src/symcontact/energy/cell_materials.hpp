#pragma once
/// \file cell_materials.hpp
/// The material law of each cell of a body: one law for every cell, or one index per cell into a list of
/// laws (a body of several materials: `[[body.material]]`, docs/input.md). Held by the elastic energies.

#include <cassert>
#include <utility>
#include <vector>

#include "symcontact/core/types.hpp"

namespace symcontact {

template <class Material>
class CellMaterials {
 public:
  /// `materials` non-empty; `cell_material` empty (the first law everywhere) or one index into `materials`
  /// per cell of a mesh of `num_cells` cells.
  CellMaterials(std::vector<Material> materials, std::vector<int> cell_material, [[maybe_unused]] Index num_cells)
      : materials_(std::move(materials)), cell_material_(std::move(cell_material)) {
    assert(!materials_.empty());
    assert(cell_material_.empty() || static_cast<Index>(cell_material_.size()) == num_cells);
  }
  /// The law of cell c.
  const Material& of(Index c) const { return materials_[cell_material_.empty() ? 0 : cell_material_[c]]; }
  const Material& front() const { return materials_.front(); }

 private:
  std::vector<Material> materials_;
  std::vector<int> cell_material_;
};

}  // namespace symcontact
