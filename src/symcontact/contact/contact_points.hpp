#pragma once
/// \file contact_points.hpp
/// The geometry step of Algorithm 2 (METHOD.md): from the current configuration, integration points on
/// the slave surface with their closest-point projections on the master (a surface or an obstacle),
/// the smoothed normal there, and the gap θ = (x − x̄)·n̄ (talk eq. 10).
///
/// Integration (2D): each slave facet is cut where the line through a master vertex v along its
/// smoothed normal n_v crosses it, so that every sub-segment projects into a single master facet and the
/// gap integrand is smooth on it (segment-based mortar integration, Puso 2004; Popp et al. 2009, §3.3);
/// each sub-segment carries Gauss–Legendre points. Weights are reference-configuration measures.
///
/// Integration (3D, segment-based mortar integration: Puso & Laursen, CMAME 193, 2004; Popp, Gee & Wall,
/// IJNME 79, 2009, §3.2): for each slave facet, the vertices of every nearby facing master facet are
/// projected along the normal n0 of the slave's vertex triangle onto its plane, in the slave's reference
/// coordinates; the reference triangle is clipped by the projected master triangle (Sutherland–Hodgman,
/// polygon_clipping.hpp), and each clip polygon is triangulated (from a vertex on flat Tri3 facets, where
/// any triangulation is exact; from its centroid on curved or bilinear ones) and carries a triangle rule
/// of degree 2·order + 1 (2·gauss_points − 1 when given): exact for θ φ on flat facets, of that degree
/// in ξ within a cell (the master's smoothed normal varies along it). Each point is evaluated on the
/// (possibly curved, Tri6) slave facet and projected onto the master by closest point, as in 2D. Curved
/// Tri6 facets are clipped through their vertex triangles (the standard approach; exact for flat facets).
/// Quadrilateral facets (Quad4, Quad9) are clipped the same way in their reference square: the master's
/// vertices projected on the plane through the slave's vertices (normal: the cross product of its
/// diagonals) are mapped to the square by inverting the bilinear map of the slave's projected vertices;
/// the polygon so clipped is exact for parallelogram slave facets (the map is then affine), and
/// approximate, like a curved facet's, for others.
/// A slave region that no projected master facet covers gets no points: past the border of the master
/// there is no contact, which the 3D end rule (contact_surface.hpp, border edges) also enforces.
///
/// A point contributes only if: its projection is not past an end of the master surface; the slave and
/// master normals face each other (n_s·n̄ < 0); and some point of its slave facet has |θ| ≤
/// search_distance. The search distance selects whole slave facets, never parts of one: the weak gap of
/// a node integrates θ φ_i over whole facets, which P2 test functions (negative over part of a facet)
/// need to keep the sign of the gap (gap_constraints.hpp).

#include <vector>

#include "symcontact/contact/bvh.hpp"
#include "symcontact/contact/contact_surface.hpp"
#include "symcontact/contact/obstacle.hpp"

namespace symcontact {

struct ContactPoint {
  Index slave_facet = -1;
  double xi[2] = {0.0, 0.0};       ///< reference coordinates on the slave facet
  double weight = 0.0;             ///< quadrature weight × reference surface Jacobian
  Index master_facet = -1;         ///< −1 for an analytic obstacle
  double eta[2] = {0.0, 0.0};      ///< reference coordinates of the projection on the master facet
  Eigen::Vector3d x = Eigen::Vector3d::Zero();     ///< current slave point
  Eigen::Vector3d xbar = Eigen::Vector3d::Zero();  ///< current projection
  Eigen::Vector3d normal = Eigen::Vector3d::Zero(); ///< unit smoothed master normal n̄ at x̄
  double gap = 0.0;                ///< θ = (x − x̄)·n̄
  /// The direction d of the frozen linearisation θ(u) ≈ (x(u) − x̄(u; η))·d (gap_constraints.hpp); zero:
  /// `normal` (the talk's frozen normal). Set by the bisector-ray projection (project_to_master()).
  Eigen::Vector3d gap_direction = Eigen::Vector3d::Zero();
  const Eigen::Vector3d& row_direction() const { return gap_direction.squaredNorm() > 0 ? gap_direction : normal; }
  Index slave_node = -1;           ///< nodal points only (nodal_contact_points): the slave surface node
};

struct ContactSearchOptions {
  double search_distance = 0.0;  ///< > 0
  int gauss_points = 0;          ///< per sub-segment; 0: 2·order + 1 (3D: see the file comment)
  /// Project along the bisector of the two sides' smoothed normals instead of to the closest point
  /// (project_to_master(), `ray_normal`); self-contact pairs (ContactPair::bisector_ray()).
  bool bisector_ray = false;
};

/// A master surface in its current configuration, ready for queries.
struct MasterGeometry {
  const ContactSurface* surface = nullptr;
  Eigen::MatrixXd x;        ///< current node positions
  Eigen::MatrixXd normals;  ///< smoothed nodal normals
  /// 2D: 4 × num_nodes; at a corner node (ContactSurface::corner) the current outward unit normals of its
  /// two facets at the node: rows 0–1 of the facet that ends there, rows 2–3 of the one that starts there
  /// (facet_end_normals(), filled at every node, read at corners only; empty in 3D).
  Eigen::MatrixXd corner_normals;
  /// The current positions of each facet's nodes (dim × nodes per facet), read by every projection.
  std::vector<Eigen::MatrixXd> facet_x;
  BoundingVolumeHierarchy tree;
};

MasterGeometry prepare_master(const ContactSurface& master, const Eigen::MatrixXd& x);

/// Projects point p (dim entries) with outward slave normal `slave_normal` on the master; fills the master
/// part of `cp` (facet, η, x, x̄, n̄, gap) and returns true when the point is a contact candidate
/// (the rules above).
/// The normal n̄ is the smoothed nodal normal interpolated on the master facet, except at a corner of a 2D
/// master (ContactSurface::corner), which is treated as a vertex of the polygon: on either facet the
/// interpolation uses that facet's own normal at the corner node (one-sided normals), and a point whose
/// closest point is the corner node itself (the fan between the two facet normals) takes the direction of
/// the corner's normal cone {a n₁ + b n₂, a, b ≥ 0} nearest to −n_s, the opposite (slave) surface's
/// normal: −n_s itself when the slave surface rests on the corner (a supporting line of the corner has
/// its normal in the cone), the nearer facet normal otherwise, which makes n̄ continuous at the edges of
/// the fan up to O(θ φ²) in the gap. Averaging the two facet normals there instead gives the bisector,
/// 45° off both facets at a right angle: the contact force at the corner then has a tangential part of
/// the order of the normal force for any slave surface that is not 45° inclined.
/// (The vertex treatment of node-to-segment contact at polygon corners, Wriggers, Computational Contact
/// Mechanics, 2nd ed., 2006, §4.1.2; the normal cone: Moreau's convex analysis.)
/// With `allow_past_end`, a point past an end of the master surface projects onto that end (used for
/// nodal friction: a slave node that hangs over the master's end can still carry pressure).
///
/// With `ray_normal` (the slave surface's SMOOTHED unit normal n_s at p), the bisector-ray projection:
/// the projection x̄ is where the line through p along the interface normal m meets the master, and
///     m = (n̄(x̄) − n_s) / |n̄(x̄) − n_s|,   θ = (p − x̄)·m,   cp.normal = m,
/// and the gap's linearisation (cp.gap_direction) is the consistent one of the ray: with m frozen, a change
/// δ of x − x̄(η) moves the foot along the facet too, and δθ = δ·n_f/(n_f·m), n_f the master facet's own
/// unit normal at x̄ (differentiate x − θ m = x_m(η) in θ and η). Freezing η and dotting with m instead
/// would miss the gap's first-order change under a slide along a facet tilted against m (the fixed
/// point then wanders along that slide, as on the crushed ring, whose contact zone ends where the
/// walls part at 20°); for the closest point the same term vanishes up to the smoothing of n̄.
/// solved as a fixed point from the closest point (m depends on x̄ through n̄; it settles in a few passes,
/// the change of n̄ along the surface being the curvature times the gap). m is the bisector of the
/// master's normal and the reversed slave normal, so both sides enter alike: at a state that is
/// mirror-symmetric about a plane (the two sides each other's reflection, n_s and n̄ reflections of each
/// other), m is the plane's normal, x̄ is the mirror image of p and θ = 2·(distance of p to the plane)
/// exactly — twice the gap of the half model on a rigid plane, where the closest point on the tilted
/// reflected facet gives 2y·cos t·(n_f·n̄) (t the facet's tilt; V7, docs/validation.md). A ray
/// projection along an averaged normal is the usual one of mortar contact (Popp, Gee & Wall, IJNME 79,
/// 2009, §3.1, with the slave's normal; here the bisector). It measures a different gap than the talk's
/// eq. 10 (closest point, master normal) only where the two sides are tilted against each other; both
/// vanish together, so the continuous constraint θ ≥ 0 is the same. Where the line meets no facing facet
/// near the closest point (past the master's end), or at a 2D corner of the master, the closest point
/// and n̄ are kept.
///
/// `candidate` (≥ 0: a master facet likely near p, such as the facet of p's mortar cell) only bounds the
/// search by its distance first: the facet found, and so every output, is the same with or without it.
bool project_to_master(const MasterGeometry& master, const Eigen::VectorXd& p, const Eigen::Vector3d& slave_normal,
                       double search, ContactPoint& cp, bool allow_past_end = false,
                       const Eigen::Vector3d* ray_normal = nullptr, Index candidate = -1);

/// One cell of the 3D segmentation: the part of slave facet f (reference coordinates, counter-clockwise)
/// covered by master facet `master_facet` projected along the slave normal.
struct MortarCell {
  Index master_facet = -1;
  std::vector<Eigen::Vector2d> polygon;
};

/// The 3D segmentation of slave facet f (xs: current slave node positions): every master facet whose box
/// overlaps the box of the prism swept by the slave facet along ±search n0 (n0 the unit normal of its
/// vertex triangle), whose vertex triangle faces the slave's and whose projection along n0 overlaps it.
std::vector<MortarCell> mortar_cells(const ContactSurface& slave, const Eigen::MatrixXd& xs, Index f,
                                     const MasterGeometry& master, double search);

/// Slave points against a master surface (xs: current slave node positions).
std::vector<ContactPoint> contact_points(const ContactSurface& slave, const Eigen::MatrixXd& xs,
                                         const MasterGeometry& master, const ContactSearchOptions& options);

/// Slave points against an analytic obstacle.
std::vector<ContactPoint> contact_points(const ContactSurface& slave, const Eigen::MatrixXd& xs,
                                         const Obstacle& obstacle, const ContactSearchOptions& options);

/// One point per slave NODE (for nodal friction): the node itself, as a point of the first facet that
/// holds it, with weight = its lumped area A_k and its projection on the master (or the obstacle); nodes
/// that project onto nothing (the rules above, with the smoothed nodal normal, except that a node past
/// an end of the master projects onto that end) are left out.
/// `master` or `obstacle` is given, not both. `bisector_ray`: the projection along the bisector
/// (project_to_master(), with the node's smoothed normal), for self-contact pairs.
std::vector<ContactPoint> nodal_contact_points(const ContactSurface& slave, const Eigen::MatrixXd& xs,
                                               const MasterGeometry* master, const Obstacle* obstacle,
                                               double search_distance, bool bisector_ray = false);

/// The interface normal of a node, outward for its side, along which its pressure is recovered
/// (surface_tractions.hpp), from its own smoothed normal n_s and the opposite side's smoothed normal n̄ at
/// its projection:
///  - one-sided pairs (obstacle, one-pass): −n̄, the only direction the constraints push in;
///  - two-sided pairs (symmetric, self-contact; `two_sided`): the bisector ν = (n_s − n̄)/|n_s − n̄|. A
///    node's force there is the sum of its own rows' (along n̄ at its points' projections) and of the
///    opposite side's rows' (along its own surface's normals near it), so it points between the two.
///    The talk's pressure is σ_n = (σ¹n¹)·n¹ = (σ²n²)·n² with n¹ = −n² (eq. 12), a single normal; the
///    discrete n_s and −n̄ differ where the facets are tilted (the edge of a curved contact zone), and
///    the bisector treats the sides alike: on a mirror-symmetric interface it is the symmetry plane's
///    normal, along which the nodal force points, while −n̄ or n_s alone are tilted by the local slope t
///    and report cos t of the force (V7 in docs/validation.md compares them with the half model). Where n_s
///    and −n̄ agree (a closed, conforming contact) the choices coincide.
///  - self-contact pairs project along the bisector already (ContactPair::bisector_ray()): their n̄ is the
///    projection's m, and the caller passes two_sided = false, so that −m is returned.
/// Used by the reported contact results (post/contact_results.hpp). The Coulomb threshold's pressure
/// keeps −n̄ (interface_normals() below), the normal of the friction term, so that the friction law holds
/// in the friction term's own decomposition. Known limit: at a corner of the surface the node's own
/// smoothed normal averages the two facets', and so does the bisector there.
/// Returns a unit vector of the size of `own`.
Eigen::VectorXd interface_normal(const Eigen::VectorXd& own, const Eigen::VectorXd& nbar, bool two_sided);

/// The one-sided interface normal at every node of `slave`, outward for the slave (dim × n): −n̄ at the
/// node's projection (nodal_contact_points), or the node's own smoothed normal where it projects onto
/// nothing. The normal of the friction term and of the Coulomb threshold's pressure.
Eigen::MatrixXd interface_normals(const ContactSurface& slave, const Eigen::MatrixXd& xs, const MasterGeometry* master,
                                  const Obstacle* obstacle, double search_distance, bool bisector_ray = false);

/// Bounding box of a facet from its node positions (for Line3/Tri6 also the Bézier control points of the
/// edges, which bound the curved facet), padded by `pad`.
BoundingVolumeHierarchy::Box facet_box(CellType type, const Eigen::MatrixXd& xf, double pad);

}  // namespace symcontact
