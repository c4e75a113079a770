#pragma once
/// \file finite_difference.hpp
/// The one shared finite-difference check of an EnergyTerm (STYLE.md §5): the gradient against
/// central differences of value(), and the Hessian (applied to random directions) against central
/// differences of the gradient. Used for every energy term.

#include <optional>

#include "symcontact/energy/energy_term.hpp"
#include "symcontact/mesh/mesh.hpp"

namespace symcontact::testing {

struct FdResult {
  double gradient_error = 0.0;  ///< max_i |g_i − (E(u+h e_i) − E(u−h e_i))/2h| / max(1, ‖g‖∞)
  double hessian_error = 0.0;   ///< max over directions of ‖H d − (g(u+hd) − g(u−hd))/2h‖∞ / max(1, ‖H d‖∞)
};

/// Checks `term` at state u. Gradient components are checked on all DOFs when u.size() ≤ max_dofs,
/// else on a random subset of max_dofs; the Hessian on `directions` random unit directions. In a sanitised
/// build (SYMCONTACT_SANITIZED: the ASan + UBSan suite of scripts/test) max_dofs is at most
/// kSanitisedMaxDofs: the sanitisers check the memory and arithmetic of the same code (value, gradient and
/// Hessian of every cell), which the gradient's 2 × max_dofs evaluations of value() only repeat (a tenfold
/// cost there: minutes per quadratic 3D cell type); the Release suite checks every component.
constexpr int kSanitisedMaxDofs = 40;

FdResult check_derivatives(const EnergyTerm& term, const VectorXd& u, double h = 1e-6, int directions = 5,
                           int max_dofs = 400, unsigned seed = 1);

/// The mesh the derivative checks run on: the rectangle [0, 2] × [0, 1] (4 × 3 squares) or the box
/// [0, 1] × [0, 1] × [0, 2] (2 × 2 × 3 cubes) of structured.hpp, of `order` 1 or 2, its interior nodes moved
/// by up to 20 % of the spacing (so that no element is a right-angled copy of another). With `tensor`, the
/// same domain in cells of that quadrilateral or hexahedron type (structured.hpp's tensor_mesh(); `order`
/// is then the type's): 4 × 3 quadrilaterals, or 2 × 2 × 2 hexahedra (one interior vertex, moved). With
/// `mixed` (Quad4 or Quad9), every other quadrilateral cut into two triangles (mixed_rectangle_mesh()); with
/// `tensor` a prism or pyramid type, the box's 2 × 2 × 3 cubes each cut into prisms or pyramids
/// (structured_mesh()).
Mesh distorted_mesh(int dim, int order, std::optional<CellType> tensor = {}, bool mixed = false);

}  // namespace symcontact::testing
