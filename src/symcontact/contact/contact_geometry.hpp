#pragma once
/// \file contact_geometry.hpp
/// The configuration a contact pair's geometry is evaluated in ([[contact]] geometry, docs/input.md).
///
///  - kCurrent: projections, normals, weights and the friction points at the iterate x = X + u, re-evaluated
///    by the geometry fixed point until they agree with its solution (Algorithm 2, METHOD.md): finite
///    sliding and rotations.
///  - kReference: all of them once, at u = 0 (x = X), and the gap used as its linearisation
///        g(u) = g(X) + A u,   A the rows of gap_constraints.hpp with the projections and normals of X,
///    the slips projected on the tangent planes of X: the classical small-sliding (linear) contact problem,
///    the one closed-form benchmarks assume. Wrong where the surfaces slide by more than a facet or turn.

namespace symcontact {

enum class ContactGeometry { kCurrent, kReference };

}  // namespace symcontact
