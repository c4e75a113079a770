#pragma once
/// \file contact_set.hpp
/// All contact pairs of a problem, and their linearisation at a given displacement (steps 1–4 of
/// Algorithm 2, METHOD.md).
///
/// A pair joins surface a to surface b (or to an obstacle). It contributes constraint *families*:
///  - symmetric: a onto b AND b onto a (no master/slave choice; the two families are nearly
///    dependent, which the interior point method tolerates),
///  - one-pass: the slave onto the master only,
///  - obstacle: a onto the obstacle,
///  - self-contact (a and b the same surface): one family, the surface onto itself, whatever the mode —
///    every point is both slave and master, so it is symmetric by construction. A point never contacts
///    its own neighbourhood: its own facet and the facets around it face the same way as the point
///    (n_s·n̄ ≥ 0), and only facing facets (n_s·n̄ < 0) are candidates (contact_points.hpp).
/// Stacking the families' rows gives g(u) = A u + b ≥ 0.

#include <optional>
#include <string>
#include <vector>

#include "symcontact/contact/contact_geometry.hpp"
#include "symcontact/contact/contact_points.hpp"
#include "symcontact/contact/gap_constraints.hpp"

namespace symcontact {

enum class ContactMode { kSymmetric, kOnePass };
enum class FrictionLaw { kNone, kTresca, kCoulomb };

/// How a frictional pair's regularisation length α is set (docs/friction.md, "Choosing α").
///  - kGivenLength: the `alpha` of the problem file, the same at every point.
///  - kElementFraction (automatic): at every friction point q, α_q = kAlphaPerElement × h_q, h_q the mean
///    size of the slave facets around the point's node. The regularised law is a stick spring τ/α below
///    |s| ≈ α, and 99 % of τ is reached at |s| = 7α: a stuck node moves by at most 0.7 % of its elements
///    before it slips, the order of the elastic slip of penalty friction, which Abaqus sets by default to
///    0.005 of the contact element length (Abaqus Analysis User's Guide, "Frictional behavior"). Tied to
///    the element, the spring keeps its ratio to the bodies' stiffness (about E/h per unit area) under
///    refinement and whatever the size of the model or the units. A length fixed by the model's size
///    instead (10⁻⁶ of it) gave springs 10⁴ times the bodies' stiffness at p/E = 0.1, on which IPOPT's
///    line search stalled.
enum class FrictionRegularisation { kGivenLength, kElementFraction };

/// The automatic α in units of the local facet size (FrictionRegularisation::kElementFraction).
constexpr double kAlphaPerElement = 1e-3;

struct ContactPair {
  std::string name;
  int surface_a = -1;
  int surface_b = -1;   ///< −1 with an obstacle
  int obstacle = -1;    ///< index into ContactSet::obstacles, or −1
  ContactMode mode = ContactMode::kSymmetric;
  bool slave_is_b = false;      ///< one-pass only
  double search_distance = 0.0; ///< resolved (> 0)
  FrictionLaw friction = FrictionLaw::kNone;
  double mu = 0.0;              ///< Coulomb coefficient
  double tau = 0.0;             ///< Tresca threshold
  FrictionRegularisation regularisation = FrictionRegularisation::kElementFraction;
  double alpha = 0.0;           ///< kGivenLength: the regularisation length (> 0)
  /// The regularisation length at a point whose slave facets have the mean size h.
  double regularisation_length(double h) const {
    return regularisation == FrictionRegularisation::kGivenLength ? alpha : kAlphaPerElement * h;
  }
  /// Where the pair's projections, normals and friction points are taken (contact_geometry.hpp).
  ContactGeometry geometry = ContactGeometry::kCurrent;
  /// Constraints push on each node from both sides (symmetric or self-contact): the reported pressure is
  /// along the bisector of the two sides' normals (contact_points.hpp, interface_normal()).
  bool two_sided() const { return obstacle < 0 && (mode == ContactMode::kSymmetric || surface_a == surface_b); }
  /// Self-contact projects along the bisector of the two sides' normals (project_to_master(), contact_points.hpp):
  /// the surface meets itself, and a mirror-symmetric fold then sees exactly twice the distance to its plane
  /// of symmetry (V7). Its interface normal is the projection's m.
  bool bisector_ray() const { return obstacle < 0 && surface_a == surface_b; }
};

/// The opposite side of a family at a displacement: the master surface's geometry there, or the pair's
/// obstacle (exactly one of the two), as nodal_contact_points() and interface_normals() take them.
struct OppositeSide {
  std::optional<MasterGeometry> master_geometry;
  const Obstacle* obstacle = nullptr;
  const MasterGeometry* master() const { return master_geometry ? &*master_geometry : nullptr; }
};

struct ContactFamily {
  int pair = -1;
  int slave = -1;    ///< surface index
  int master = -1;   ///< surface index, or −1 for the pair's obstacle
};

/// The constraints at one linearisation point.
struct ContactLinearization {
  SparseMatrix A;                 ///< rows × num_dofs
  VectorXd b;
  std::vector<int> row_family;    ///< family of each row
  std::vector<Index> row_node;    ///< slave surface node of each row
  std::vector<double> row_support;///< Σ w φ_i of each row
  std::vector<std::vector<ContactPoint>> points;  ///< per family
};

/// Per-row values of earlier rows (rows `family`, `node`, values `values`) carried to the rows of `to` by their
/// family and slave node, the identity of a row across geometry iterations; 0 on a row new to `to`.
VectorXd values_on_rows(const std::vector<int>& family, const std::vector<Index>& node, const VectorXd& values,
                        const ContactLinearization& to);

class ContactSet {
 public:
  std::vector<ContactSurface> surfaces;
  std::vector<Obstacle> obstacles;
  std::vector<ContactPair> pairs;

  /// Derives the families from the pairs (call after filling pairs).
  void finalize();
  const std::vector<ContactFamily>& families() const { return families_; }
  /// The family that carries the pair's friction (its first: slave a, or the one-pass slave).
  int friction_family(int pair) const;
  /// The opposite side of family f at the configuration X + u.
  OppositeSide opposite_side(int f, const DofMap& dofs, const VectorXd& u) const;
  /// The displacement pair p's geometry is evaluated at: u for ContactGeometry::kCurrent, 0 (the
  /// reference configuration X) for kReference. Every caller that takes projections, normals or friction
  /// points of the pair at a displacement passes it this.
  VectorXd geometry_displacement(int pair, const VectorXd& u) const;
  bool empty() const { return pairs.empty(); }

  /// Projections, normals and gap constraints from the configuration X + u (X for a pair in
  /// ContactGeometry::kReference: its rows are then g = g(X) + A u whatever u).
  ContactLinearization linearize(const DofMap& dofs, const VectorXd& u) const;

  /// The default search distance of a pair: 0.1 × the diagonal of the bounding box of its surfaces
  /// (reference configuration) + 2 × their largest facet size.
  static double automatic_search_distance(const ContactSurface& a, const ContactSurface* b);

 private:
  std::vector<ContactFamily> families_;
};

}  // namespace symcontact
