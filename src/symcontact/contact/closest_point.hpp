#pragma once
/// \file closest_point.hpp
/// Closest-point projection of a point onto one contact facet: Line2/Line3 in 2D, Tri3/Tri6 and
/// Quad4/Quad8/Quad9 in 3D. The facet is x(η) = Σ_a N_a(η) x_a, η in the reference cell ([0, 1]; η1, η2 ≥ 0,
/// η1 + η2 ≤ 1; or [0, 1]²).
///  - Line2: closed form; Line3: safeguarded Newton on the stationarity condition (x(η) − p)·x'(η) = 0
///    (Wriggers, Computational Contact Mechanics, 2006, §4.1), compared with the ends.
///  - Tri3: closed form on the plane of the triangle; when the foot of the perpendicular is outside,
///    the closest point of the three edges (segments), i.e. on an edge or at a vertex (Ericson,
///    Real-Time Collision Detection, 2005, §5.1.5).
///  - Tri6: safeguarded Newton on (η1, η2) with the stationarity conditions (x(η) − p)·∂x/∂η_i = 0
///    (Gauss–Newton where the Hessian is not positive definite, steps limited), started from the
///    projection on the vertex triangle; compared with the closest points of the three boundary edges,
///    which are Line3 curves. The interior stationary point wins ties.
///  - Quad4, Quad8, Quad9 (bilinear, serendipity, biquadratic): the same Newton, started from the centre,
///    compared with the closest points of the four edges (segments, or Line3 curves).
/// The report tells where the closest point is: inside (a true normal projection), on edge e (3D),
/// or at vertex v. Facet edges are numbered like their edge nodes: triangle e0 = (0, 1), e1 = (1, 2),
/// e2 = (2, 0); quadrilateral e0 = (0, 1), e1 = (1, 2), e2 = (2, 3), e3 = (3, 0) (facet_edge()).

#include <Eigen/Core>

#include "symcontact/mesh/cell_type.hpp"

namespace symcontact {

struct FacetProjection {
  double eta[2] = {0.0, 0.0};  ///< reference coordinates of the closest point (η, or (η1, η2) in 3D)
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  double distance2 = 0.0;
  /// −1 unless the closest point was clamped to a vertex of the facet: then its local index.
  int clamped_vertex = -1;
  /// 3D only: −1 unless the closest point was clamped to the interior of an edge of the facet (local
  /// edge index, see the file comment). Inside the facet iff both are −1.
  int clamped_edge = -1;
  bool inside() const { return clamped_vertex < 0 && clamped_edge < 0; }
};

/// `xf` is dim × npf (facet node positions), p has dim entries (3 for triangles).
FacetProjection project_on_facet(CellType type, const Eigen::MatrixXd& xf, const Eigen::VectorXd& p);

/// Local vertices (a, b) of edge e of a triangle (e0 = (0, 1), e1 = (1, 2), e2 = (2, 0)); the Tri6 node of
/// the edge is 3 + e.
inline const int* triangle_edge(int e) {
  static const int edges[3][2] = {{0, 1}, {1, 2}, {2, 0}};
  return edges[e];
}

/// Number of edges of a 3D facet (3 for a triangle, 4 for a quadrilateral).
int facet_num_edges(CellType t);

/// Local vertices (a, b) of edge e of a triangle or quadrilateral facet (triangle_edge(), or
/// (e, e + 1 mod 4)); the edge's node of a Tri6 / Quad9 is 3 + e / 4 + e.
const int* facet_edge(CellType t, int e);

/// Moves triangle reference coordinates slightly outside the reference triangle back onto it: negative
/// ones to 0, then (η1, η2) scaled so that η1 + η2 ≤ 1.
void snap_into_triangle(double* eta);

/// Moves reference coordinates of a 3D facet onto it: snap_into_triangle(), or each clamped to [0, 1].
/// Returns whether they were within `tol` of it.
bool snap_into_facet(CellType t, double* eta, double tol);

/// Triangle reference coordinates (η1, η2) of the point at parameter t ∈ [0, 1] along edge e (from its
/// vertex a to its vertex b).
void triangle_edge_point(int e, double t, double* eta);

}  // namespace symcontact
