#pragma once
/// \file bvh.hpp
/// A bounding-volume hierarchy of axis-aligned boxes (2D boxes have z = 0), for contact search in
/// O(log n) per query instead of O(n). Built top-down by splitting at the median centroid along the
/// longest axis: O(n log n) to build, n leaves, 2n − 1 nodes.

#include <Eigen/Geometry>
#include <functional>
#include <vector>

namespace symcontact {

class BoundingVolumeHierarchy {
 public:
  using Box = Eigen::AlignedBox3d;

  void build(const std::vector<Box>& boxes);
  std::size_t size() const { return num_items_; }

  /// Calls visit(item) for every item whose box intersects `query`.
  void for_each_overlap(const Box& query, const std::function<void(int)>& visit) const;

  /// The item minimising distance(item) (a squared distance, ≥ the squared distance from p to the
  /// item's box), among items whose box lies within sqrt(max_dist2) of p; −1 if none. Boxes farther than
  /// the best distance found so far are skipped.
  int nearest(const Eigen::Vector3d& p, double max_dist2, const std::function<double(int)>& distance2,
              double* best_dist2 = nullptr) const;

  /// As above, with distance2(item, bound) told the best squared distance so far: for an item that cannot
  /// win it may return any value > bound without finishing its work.
  int nearest_within_bound(const Eigen::Vector3d& p, double max_dist2,
                           const std::function<double(int, double)>& distance2, double* best_dist2 = nullptr) const;

 private:
  struct Node {
    Box box;
    int left = -1, right = -1;  ///< children, or −1 for a leaf
    int item = -1;              ///< leaf item
  };
  int build_range(std::vector<int>& items, int begin, int end, const std::vector<Box>& boxes);
  std::vector<Node> nodes_;
  std::size_t num_items_ = 0;
};

}  // namespace symcontact
