#pragma once
/// \file cell_dispatch.hpp
/// Turns a run-time CellType into compile-time sizes, so kernels work on fixed-size Eigen arrays:
/// dispatch_cell(t, f) calls f(std::integral_constant<int, D>{}, std::integral_constant<int, NN>{})
/// with D the cell's dimension and NN its number of nodes.

#include <stdexcept>
#include <type_traits>

#include "symcontact/mesh/cell_type.hpp"

namespace symcontact {

template <class F>
decltype(auto) dispatch_cell(CellType t, F&& f) {
  using std::integral_constant;
  switch (t) {
    case CellType::kLine2: return f(integral_constant<int, 1>{}, integral_constant<int, 2>{});
    case CellType::kLine3: return f(integral_constant<int, 1>{}, integral_constant<int, 3>{});
    case CellType::kTri3: return f(integral_constant<int, 2>{}, integral_constant<int, 3>{});
    case CellType::kTri6: return f(integral_constant<int, 2>{}, integral_constant<int, 6>{});
    case CellType::kTet4: return f(integral_constant<int, 3>{}, integral_constant<int, 4>{});
    case CellType::kTet10: return f(integral_constant<int, 3>{}, integral_constant<int, 10>{});
    case CellType::kQuad4: return f(integral_constant<int, 2>{}, integral_constant<int, 4>{});
    case CellType::kQuad8: return f(integral_constant<int, 2>{}, integral_constant<int, 8>{});
    case CellType::kQuad9: return f(integral_constant<int, 2>{}, integral_constant<int, 9>{});
    case CellType::kHex8: return f(integral_constant<int, 3>{}, integral_constant<int, 8>{});
    case CellType::kHex20: return f(integral_constant<int, 3>{}, integral_constant<int, 20>{});
    case CellType::kHex27: return f(integral_constant<int, 3>{}, integral_constant<int, 27>{});
    case CellType::kPrism6: return f(integral_constant<int, 3>{}, integral_constant<int, 6>{});
    case CellType::kPrism18: return f(integral_constant<int, 3>{}, integral_constant<int, 18>{});
    case CellType::kPrism15: return f(integral_constant<int, 3>{}, integral_constant<int, 15>{});
    case CellType::kPyramid5: return f(integral_constant<int, 3>{}, integral_constant<int, 5>{});
    case CellType::kPyramid13: return f(integral_constant<int, 3>{}, integral_constant<int, 13>{});
    case CellType::kPyramid14: return f(integral_constant<int, 3>{}, integral_constant<int, 14>{});
    default: break;
  }
  throw std::logic_error("dispatch_cell: unsupported cell type " + cell_name(t));
}

}  // namespace symcontact
