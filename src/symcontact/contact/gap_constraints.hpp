#pragma once
/// \file gap_constraints.hpp
/// Weak (mortar-like) gap constraints of one slave surface against its master, linear in u once the
/// projections and normals are frozen (Algorithm 2, step 2):
///
///   g_i(u) = Σ_q w_q φ_i(ξ_q) θ_q(u) ≥ 0,   θ_q(u) = (x_s(ξ_q) − x̄_q)·n̄_q,
///   x_s(ξ) = Σ_a N_a(ξ)(X_a + u_a),   x̄ = Σ_b M_b(η)(Y_b + u_b)  (fixed for an obstacle),
///
/// one row per slave surface node i with at least one contributing point. φ_i are the test functions of
/// contact_surface.hpp: the trace shape functions N_i, except on Tri6 facets (a modified quadratic basis
/// whose every function integrates positively). g(u) = A u + b with A in global DOF numbering.
/// Rows whose support Σ_q w_q φ_i(ξ_q) is not positive (partly integrated P2 facets) are left out.

#include <vector>

#include "symcontact/contact/contact_points.hpp"
#include "symcontact/fem/dof_map.hpp"

namespace symcontact {

struct GapConstraints {
  std::vector<Triplet> A;        ///< (row, global DOF, value)
  std::vector<double> b;         ///< constant part, one per row
  std::vector<Index> slave_node; ///< slave surface node of each row
  std::vector<double> support;   ///< Σ_q w_q φ_i(ξ_q): the row's weight (for nodal average gaps)
  Index num_rows() const { return static_cast<Index>(b.size()); }
};

/// `master` is null for an obstacle. Row indices start at 0.
GapConstraints assemble_gap_constraints(const ContactSurface& slave, const ContactSurface* master,
                                        const std::vector<ContactPoint>& points, const DofMap& dofs);

}  // namespace symcontact
