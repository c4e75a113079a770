#include "symcontact/contact/bvh.hpp"

#include <algorithm>
#include <array>
#include <utility>

namespace symcontact {

void BoundingVolumeHierarchy::build(const std::vector<Box>& boxes) {
  nodes_.clear();
  num_items_ = boxes.size();
  if (boxes.empty()) return;
  nodes_.reserve(2 * boxes.size());
  std::vector<int> items(boxes.size());
  for (std::size_t i = 0; i < items.size(); ++i) items[i] = static_cast<int>(i);
  build_range(items, 0, static_cast<int>(items.size()), boxes);
}

int BoundingVolumeHierarchy::build_range(std::vector<int>& items, int begin, int end, const std::vector<Box>& boxes) {
  const int id = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  Box box;
  box.setEmpty();
  for (int i = begin; i < end; ++i) box.extend(boxes[items[i]]);
  nodes_[id].box = box;
  if (end - begin == 1) {
    nodes_[id].item = items[begin];
    return id;
  }
  int axis;
  box.sizes().maxCoeff(&axis);
  const int mid = (begin + end) / 2;
  std::nth_element(items.begin() + begin, items.begin() + mid, items.begin() + end,
                   [&](int a, int b) { return boxes[a].center()[axis] < boxes[b].center()[axis]; });
  const int l = build_range(items, begin, mid, boxes);
  const int r = build_range(items, mid, end, boxes);
  nodes_[id].left = l;
  nodes_[id].right = r;
  return id;
}

void BoundingVolumeHierarchy::for_each_overlap(const Box& query, const std::function<void(int)>& visit) const {
  if (nodes_.empty()) return;
  std::vector<int> stack{0};
  while (!stack.empty()) {
    const Node& n = nodes_[stack.back()];
    stack.pop_back();
    if (!n.box.intersects(query)) continue;
    if (n.item >= 0) {
      visit(n.item);
    } else {
      stack.push_back(n.left);
      stack.push_back(n.right);
    }
  }
}

int BoundingVolumeHierarchy::nearest(const Eigen::Vector3d& p, double max_dist2,
                                     const std::function<double(int)>& distance2, double* best_dist2) const {
  return nearest_within_bound(p, max_dist2, [&](int item, double) { return distance2(item); }, best_dist2);
}

int BoundingVolumeHierarchy::nearest_within_bound(const Eigen::Vector3d& p, double max_dist2,
                                                  const std::function<double(int, double)>& distance2,
                                                  double* best_dist2) const {
  int best = -1;
  double best_d2 = max_dist2;
  if (!nodes_.empty()) {
    // Depth-first, a node's two children replacing it on the stack: it never holds more than the tree's
    // depth + 1 entries (at most 2 + log₂ n with the median split), so a fixed array serves (no allocation
    // in a query made for every quadrature point).
    std::array<std::pair<double, int>, 80> stack;
    int top = 0;
    stack[top++] = {nodes_[0].box.squaredExteriorDistance(p), 0};
    while (top > 0) {
      const auto [lb, id] = stack[--top];
      if (lb > best_d2) continue;
      const Node& n = nodes_[id];
      if (n.item >= 0) {
        const double d2 = distance2(n.item, best_d2);
        if (d2 <= best_d2) {
          best_d2 = d2;
          best = n.item;
        }
        continue;
      }
      const double dl = nodes_[n.left].box.squaredExteriorDistance(p);
      const double dr = nodes_[n.right].box.squaredExteriorDistance(p);
      // Visit the nearer child first (pushed last).
      if (dl < dr) {
        stack[top++] = {dr, n.right};
        stack[top++] = {dl, n.left};
      } else {
        stack[top++] = {dl, n.left};
        stack[top++] = {dr, n.right};
      }
    }
  }
  if (best_dist2) *best_dist2 = best_d2;
  return best;
}

}  // namespace symcontact
