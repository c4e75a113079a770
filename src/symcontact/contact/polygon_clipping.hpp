#pragma once
/// \file polygon_clipping.hpp
/// Plane convex polygons for segment-based 3D mortar integration (Puso & Laursen, CMAME 193, 2004;
/// Popp, Gee & Wall, IJNME 79, 2009, §3.2): the intersection of a slave facet and a projected master
/// facet is a convex polygon, clipped by Sutherland–Hodgman (Sutherland & Hodgman, CACM 17, 1974)
/// and triangulated from its centroid.
///
/// Polygons are lists of vertices in counter-clockwise order (positive signed area).

#include <Eigen/Core>
#include <array>
#include <vector>

namespace symcontact {

using Polygon2 = std::vector<Eigen::Vector2d>;

/// Signed area (> 0 for counter-clockwise vertices).
double polygon_area(const Polygon2& p);

/// The part of `subject` inside the convex counter-clockwise polygon `clip` (Sutherland–Hodgman: the
/// subject is cut by the half-plane left of each clip edge in turn). Both convex: the result is convex
/// and counter-clockwise, or empty. Vertices closer than `merge_tol` (relative to the clip's size) to
/// the previous one are merged, so that a shared edge does not create slivers.
Polygon2 clip_convex_polygon(const Polygon2& subject, const Polygon2& clip, double merge_tol = 1e-12);

/// Fan triangulation from the vertex centroid: triangles (c, p_k, p_{k+1}), k = 0..n−1, for a convex polygon.
std::vector<std::array<Eigen::Vector2d, 3>> triangulate_from_centroid(const Polygon2& p);

/// Fan triangulation from the first vertex: triangles (p_0, p_k, p_{k+1}), k = 1..n−2, for a convex polygon.
std::vector<std::array<Eigen::Vector2d, 3>> triangulate_from_vertex(const Polygon2& p);

}  // namespace symcontact
