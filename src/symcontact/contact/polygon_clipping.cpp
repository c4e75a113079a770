#include "symcontact/contact/polygon_clipping.hpp"

#include <algorithm>
#include <cmath>

namespace symcontact {

double polygon_area(const Polygon2& p) {
  double a = 0.0;
  const std::size_t n = p.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Eigen::Vector2d& u = p[k];
    const Eigen::Vector2d& v = p[(k + 1) % n];
    a += u.x() * v.y() - u.y() * v.x();
  }
  return 0.5 * a;
}

Polygon2 clip_convex_polygon(const Polygon2& subject, const Polygon2& clip, double merge_tol) {
  double size = 0.0;
  for (const auto& c : clip) size = std::max(size, c.cwiseAbs().maxCoeff());
  for (const auto& s : subject) size = std::max(size, s.cwiseAbs().maxCoeff());
  const double tol = merge_tol * std::max(size, 1e-300);
  Polygon2 out = subject;
  const std::size_t nc = clip.size();
  for (std::size_t e = 0; e < nc && !out.empty(); ++e) {
    const Eigen::Vector2d a = clip[e], b = clip[(e + 1) % nc];
    const Eigen::Vector2d d = b - a;
    const double len = d.norm();
    if (len == 0.0) continue;
    // Signed distance to the left of a → b.
    auto side = [&](const Eigen::Vector2d& p) { return (d.x() * (p.y() - a.y()) - d.y() * (p.x() - a.x())) / len; };
    Polygon2 in = std::move(out);
    out.clear();
    const std::size_t n = in.size();
    for (std::size_t k = 0; k < n; ++k) {
      const Eigen::Vector2d& p = in[k];
      const Eigen::Vector2d& q = in[(k + 1) % n];
      double sp = side(p), sq = side(q);
      // Points within round-off of the clip line count as on it (inside).
      if (std::abs(sp) <= tol) sp = 0.0;
      if (std::abs(sq) <= tol) sq = 0.0;
      if (sp >= 0.0) out.push_back(p);
      if ((sp > 0.0 && sq < 0.0) || (sp < 0.0 && sq > 0.0)) out.push_back(p + (sp / (sp - sq)) * (q - p));
    }
    // Merge coincident consecutive vertices.
    Polygon2 merged;
    for (const auto& p : out)
      if (merged.empty() || (p - merged.back()).norm() > tol) merged.push_back(p);
    while (merged.size() > 1 && (merged.front() - merged.back()).norm() <= tol) merged.pop_back();
    out = std::move(merged);
  }
  if (out.size() < 3) out.clear();
  return out;
}

std::vector<std::array<Eigen::Vector2d, 3>> triangulate_from_centroid(const Polygon2& p) {
  std::vector<std::array<Eigen::Vector2d, 3>> t;
  if (p.size() < 3) return t;
  if (p.size() == 3) {
    t.push_back({p[0], p[1], p[2]});
    return t;
  }
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  for (const auto& v : p) c += v;
  c /= static_cast<double>(p.size());
  for (std::size_t k = 0; k < p.size(); ++k) t.push_back({c, p[k], p[(k + 1) % p.size()]});
  return t;
}

std::vector<std::array<Eigen::Vector2d, 3>> triangulate_from_vertex(const Polygon2& p) {
  std::vector<std::array<Eigen::Vector2d, 3>> t;
  for (std::size_t k = 1; k + 1 < p.size(); ++k) t.push_back({p[0], p[k], p[k + 1]});
  return t;
}

}  // namespace symcontact
