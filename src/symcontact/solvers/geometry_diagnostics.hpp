#pragma once
/// \file geometry_diagnostics.hpp
/// What the geometry fixed point (geometry_fixed_point.hpp) tells the user about the contact it sees: a pair
/// with no contact point at all (a warning), and at debug level what each iteration changed.

#include <vector>

#include "symcontact/contact/contact_set.hpp"
#include "symcontact/core/log.hpp"
#include "symcontact/fem/dof_map.hpp"

namespace symcontact {

/// Warns of every pair of `contacts` with no point in `lin`: usually a mistake (a meshed obstacle whose facets
/// face away, a search distance too small) that would let the bodies pass through each other.
void warn_pairs_without_points(const ContactSet& contacts, const ContactLinearization& lin, const Logger& log);

/// Debug log of one geometry iteration: where the displacement changed most (du), and which constraint rows
/// (family, slave surface node) came and went since the previous linearisation (prev_family, prev_node; empty
/// at the first) — what a fixed point that wanders or cycles is doing.
void log_geometry_change(const VectorXd& du, const DofMap& dofs, const ContactLinearization& lin,
                         const std::vector<int>& prev_family, const std::vector<Index>& prev_node, const Logger& log);

}  // namespace symcontact
