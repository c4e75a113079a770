#pragma once
/// \file penetration.hpp
/// A global test of how far the contact surfaces of each pair have gone into each other, independent of
/// the contact search (no search distance, no active set): the check behind "the bodies passed through
/// each other" at the end of a load step (post/step_checks.hpp) and "the bodies overlap at the start"
/// before the solve (model/setup_checks.hpp).
///
/// For every node k of a slave surface S (both sides of a symmetric pair, the slave of a one-pass pair,
/// surface a against an obstacle), at displacement u, against the opposite side M:
///  - **inside the other body**: x_k lies in a cell of M's body (the vertex simplex of the cell, found
///    with a bounding-volume hierarchy over all the body's cells); depth = the distance from x_k to the
///    nearest point of M (nearest facet over the whole of M, also a BVH search);
///  - **passed through M**: the nearest point of M is inside a facet (a true normal projection) and the
///    signed distance d = (x_k − x̄)·n̄ along that facet's unit normal n̄ is below −tol, while the same
///    measure in the reference configuration was ≥ −tol: the node started in front of M and is now
///    behind it, although possibly outside the body (a body pushed right through). depth = −d;
///  - **analytic obstacle**: depth = −(x_k − x̄)·n̄ with Obstacle::project() (exact, global).
/// A node penetrates when its depth exceeds tol_k = relative_tolerance × h_k, h_k the local element size:
/// the larger of the longest reference facet of S at node k and the reference diameter of the nearest
/// facet of M. Contact imposed in weak form lets single nodes pass the opposite surface by a fraction of h,
/// most at a sharp corner of a surface (O(h²/R) against a curve of radius R): at most 1.1 % of h in the Hertz
/// (2D, 3D), rings, inclined-interface and friction-block examples (summary.json, max_penetration_ratio),
/// up to 15.4 % at the sharp, dragged corner of the slab in ironing_2d/ironing_mu0.3 (load steps 51–52). Hence a relative tolerance rather than zero, with a margin over that figure; bodies
/// driven through each other measure hundreds of percent.
///
/// Self-contact pairs (a = b) are skipped (every node lies in its own body); between two surfaces of one body
/// only the "passed through" test applies. A meshed rigid obstacle has
/// no cells: only the "passed through" test applies to it. In the reference configuration (u = 0) the
/// "passed through" test never fires (reference and current measures agree), so only nodes inside the
/// other body and nodes behind an analytic obstacle count there.

#include <string>
#include <vector>

#include "symcontact/contact/contact_set.hpp"
#include "symcontact/fem/dof_map.hpp"
#include "symcontact/mesh/mesh.hpp"

namespace symcontact {

/// Default relative_tolerance of find_penetrations(): 25 % of the local element size (see above).
constexpr double kPenetrationRelativeTolerance = 0.25;

/// The deepest node of one side of a pair (largest depth / h).
struct Penetration {
  int pair = -1;
  int slave = -1;          ///< surface index of the penetrating node
  int master = -1;         ///< surface index it went into, or −1 for the pair's analytic obstacle
  Index node = -1;         ///< slave surface node (ContactSurface::nodes index)
  double depth = 0.0;      ///< how far, in length units
  double size = 0.0;       ///< h at the node (the tolerance is relative_tolerance × size)
  bool passed_through = false;  ///< found behind M but outside its body
  double ratio() const { return size > 0 ? depth / size : 0.0; }
  /// Whether the depth exceeds relative_tolerance × h: a penetration, not the slack of weak contact.
  bool exceeds(double relative_tolerance = kPenetrationRelativeTolerance) const {
    return depth > relative_tolerance * size;
  }
};


/// For every pair and slave side, the node of largest depth / h (none when no node has a positive depth;
/// Penetration::exceeds() tells whether it is beyond the tolerance). relative_tolerance also sets which nodes
/// count as "in front" in the reference configuration for the "passed through" test. `meshes[b]` is the mesh
/// of body b (cells used for the point-in-body test).
std::vector<Penetration> find_penetrations(const ContactSet& contacts, const std::vector<const Mesh*>& meshes,
                                           const DofMap& dofs, const VectorXd& u,
                                           double relative_tolerance = kPenetrationRelativeTolerance);

/// For every family of a pair in ContactGeometry::kReference (small sliding), the node of largest violation of
/// the linearised gap its solve enforces: depth = −g_i(u) / s_i, g = A u + b the rows of `lin` (frozen at the
/// reference configuration, gap_constraints.hpp) and s_i their supports Σ w φ_i, so that g_i / s_i is the
/// nodal average gap; size = the longest reference facet of the slave surface at the node. Pairs in
/// ContactGeometry::kCurrent are skipped: find_penetrations() measures them in the deformed configuration,
/// which for a small-sliding pair tells how far the motion is from small sliding, not whether its solve held.
std::vector<Penetration> find_linearized_penetrations(const ContactSet& contacts, const ContactLinearization& lin,
                                                      const VectorXd& u);

/// The rows of `lin` whose every DOF is prescribed (`is_fixed`, one entry per DOF): a node held by Dirichlet
/// conditions along its contact normal (and, in a pair, the opposite side's nodes too). Their gaps A u + b
/// are the prescribed displacements' alone: no contact force moves them, and their multipliers take whatever
/// part of the supports' reactions the solve leaves them (an overconstraint, as in any FE code).
std::vector<char> held_rows(const ContactLinearization& lin, const std::vector<char>& is_fixed);

/// For every family, the node of largest depth −g_i(u) / s_i among the `held` rows (held_rows()), measured as
/// find_linearized_penetrations() measures its rows.
std::vector<Penetration> find_held_penetrations(const ContactSet& contacts, const ContactLinearization& lin,
                                                const VectorXd& u, const std::vector<char>& held);

/// Signed distance of each point (columns of `points`, dim × n) to the nearest facet of surface `s` (node
/// positions x, dim × num_nodes), found over the whole surface with a bounding-volume hierarchy, the sign
/// by that facet's unit normal (facet_normal()) at the closest point; NaN where the closest point is not
/// inside a facet (an end, edge or vertex: no side can be told).
Eigen::VectorXd signed_distances(const ContactSurface& s, const Eigen::MatrixXd& x, const Eigen::MatrixXd& points);

}  // namespace symcontact
