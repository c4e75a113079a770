#include "symcontact/contact/bvh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

using namespace symcontact;
using Box = BoundingVolumeHierarchy::Box;

namespace {

/// Random boxes with corners in [0, 1]^d and sizes up to `max_size` (z = 0 for d = 2).
std::vector<Box> random_boxes(int n, int d, double max_size, std::mt19937& rng) {
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::vector<Box> boxes;
  for (int i = 0; i < n; ++i) {
    Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Zero();
    for (int k = 0; k < d; ++k) {
      lo[k] = U(rng);
      hi[k] = lo[k] + max_size * U(rng);
    }
    boxes.emplace_back(lo, hi);
  }
  return boxes;
}

/// A random point inside box b (z = 0 in 2D since the box is flat).
Eigen::Vector3d point_in(const Box& b, std::mt19937& rng) {
  std::uniform_real_distribution<double> U(0.0, 1.0);
  Eigen::Vector3d t(U(rng), U(rng), U(rng));
  return b.min() + t.cwiseProduct(b.max() - b.min());
}

std::set<int> tree_overlaps(const BoundingVolumeHierarchy& tree, const Box& q) {
  std::set<int> out;
  tree.for_each_overlap(q, [&](int i) { EXPECT_TRUE(out.insert(i).second) << "item " << i << " visited twice"; });
  return out;
}

std::set<int> brute_overlaps(const std::vector<Box>& boxes, const Box& q) {
  std::set<int> out;
  for (int i = 0; i < static_cast<int>(boxes.size()); ++i)
    if (boxes[i].intersects(q)) out.insert(i);
  return out;
}

}  // namespace

class BvhDim : public ::testing::TestWithParam<int> {};

TEST_P(BvhDim, OverlapsEqualBruteForce) {
  const int d = GetParam();
  std::mt19937 rng(100 + d);
  for (int n : {1, 2, 3, 7, 200}) {
    const std::vector<Box> boxes = random_boxes(n, d, 0.1, rng);
    BoundingVolumeHierarchy tree;
    tree.build(boxes);
    EXPECT_EQ(tree.size(), static_cast<std::size_t>(n));
    int nonempty = 0;
    for (const Box& q : random_boxes(100, d, 0.3, rng)) {
      const std::set<int> got = tree_overlaps(tree, q), want = brute_overlaps(boxes, q);
      EXPECT_EQ(got, want) << "n = " << n;
      nonempty += !want.empty();
    }
    // Every box overlaps itself.
    for (int i = 0; i < n; ++i) EXPECT_TRUE(tree_overlaps(tree, boxes[i]).count(i));
    if (n == 200) {
      EXPECT_GT(nonempty, 20);  // the queries do exercise hits
    }
  }
}

TEST_P(BvhDim, NearestEqualsBruteForceMinimiser) {
  const int d = GetParam();
  std::mt19937 rng(200 + d);
  std::uniform_real_distribution<double> U(-0.2, 1.2);
  const int n = 150;
  const std::vector<Box> boxes = random_boxes(n, d, 0.08, rng);
  // Each item is a point inside its box; distance2 = squared distance to it (≥ distance to the box).
  std::vector<Eigen::Vector3d> site(n);
  for (int i = 0; i < n; ++i) site[i] = point_in(boxes[i], rng);
  BoundingVolumeHierarchy tree;
  tree.build(boxes);
  for (int trial = 0; trial < 200; ++trial) {
    Eigen::Vector3d p(U(rng), U(rng), d == 3 ? U(rng) : 0.0);
    int calls = 0;
    auto dist2 = [&](int i) {
      ++calls;
      return (site[i] - p).squaredNorm();
    };
    int want = -1;
    double want_d2 = std::numeric_limits<double>::infinity();
    for (int i = 0; i < n; ++i)
      if ((site[i] - p).squaredNorm() < want_d2) want_d2 = (site[want = i] - p).squaredNorm();
    double got_d2 = -1.0;
    const int got = tree.nearest(p, 1e30, dist2, &got_d2);
    ASSERT_GE(got, 0);
    EXPECT_EQ(got, want);
    EXPECT_DOUBLE_EQ(got_d2, want_d2);
    EXPECT_LT(calls, n) << "no pruning at all";
    // A radius just above the minimum still finds it; just below finds nothing.
    EXPECT_EQ(tree.nearest(p, want_d2 * (1 + 1e-9) + 1e-300, dist2), want);
    EXPECT_EQ(tree.nearest(p, want_d2 * (1 - 1e-9), dist2), -1);
    // Told the best distance so far, an item that cannot win may stop early (+∞): same answer, and
    // every bound is at least the answer's distance.
    double smallest_bound = std::numeric_limits<double>::infinity();
    const auto bounded = [&](int i, double bound) {
      smallest_bound = std::min(smallest_bound, bound);
      const double d2 = (site[i] - p).squaredNorm();
      return d2 > bound ? std::numeric_limits<double>::infinity() : d2;
    };
    double bounded_d2 = -1.0;
    EXPECT_EQ(tree.nearest_within_bound(p, 1e30, bounded, &bounded_d2), want);
    EXPECT_DOUBLE_EQ(bounded_d2, want_d2);
    EXPECT_GE(smallest_bound, want_d2);
  }
}

TEST_P(BvhDim, NearestToSegmentsInsideBoxes) {
  // Items are segments, each the diagonal of its box: distance2 is the squared point–segment distance.
  const int d = GetParam();
  std::mt19937 rng(300 + d);
  std::uniform_real_distribution<double> U(-0.1, 1.1);
  const std::vector<Box> boxes = random_boxes(120, d, 0.15, rng);
  auto seg_d2 = [&](int i, const Eigen::Vector3d& p) {
    const Eigen::Vector3d a = boxes[i].min(), b = boxes[i].max();
    const double L2 = (b - a).squaredNorm();
    const double t = L2 > 0 ? std::clamp((p - a).dot(b - a) / L2, 0.0, 1.0) : 0.0;
    return (a + t * (b - a) - p).squaredNorm();
  };
  BoundingVolumeHierarchy tree;
  tree.build(boxes);
  for (int trial = 0; trial < 100; ++trial) {
    const Eigen::Vector3d p(U(rng), U(rng), d == 3 ? U(rng) : 0.0);
    double want_d2 = std::numeric_limits<double>::infinity();
    for (int i = 0; i < static_cast<int>(boxes.size()); ++i) want_d2 = std::min(want_d2, seg_d2(i, p));
    double got_d2 = -1;
    const int got = tree.nearest(p, 4.0, [&](int i) { return seg_d2(i, p); }, &got_d2);
    ASSERT_GE(got, 0);
    EXPECT_DOUBLE_EQ(seg_d2(got, p), want_d2);
    EXPECT_DOUBLE_EQ(got_d2, want_d2);
  }
}

INSTANTIATE_TEST_SUITE_P(Bvh, BvhDim, ::testing::Values(2, 3), [](const ::testing::TestParamInfo<int>& param_info) {
  return "Dim" + std::to_string(param_info.param);
});

TEST(Bvh, NearestRespectsMaxDistance) {
  std::vector<Box> boxes{Box(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 0)),
                         Box(Eigen::Vector3d(3, 0, 0), Eigen::Vector3d(4, 1, 0))};
  BoundingVolumeHierarchy tree;
  tree.build(boxes);
  const Eigen::Vector3d p(2.0, 0.5, 0.0);  // 1 from each box
  auto dist2 = [&](int i) { return boxes[i].squaredExteriorDistance(p); };
  EXPECT_EQ(tree.nearest(p, 0.5, dist2), -1);
  EXPECT_GE(tree.nearest(p, 1.0, dist2), 0);
  // Items whose box is within reach but whose own distance is not are not returned.
  auto far = [&](int) { return 10.0; };
  EXPECT_EQ(tree.nearest(p, 2.0, far), -1);
  const Eigen::Vector3d q(-0.5, 0.5, 0.0);
  auto dist2_q = [&](int i) { return boxes[i].squaredExteriorDistance(q); };  // 0.25 to box 0
  EXPECT_EQ(tree.nearest(q, 0.3, dist2_q), 0);
  EXPECT_EQ(tree.nearest(q, 0.2, dist2_q), -1);
}

TEST(Bvh, EmptyTree) {
  BoundingVolumeHierarchy tree;
  tree.build({});
  EXPECT_EQ(tree.size(), 0u);
  int visits = 0;
  tree.for_each_overlap(Box(Eigen::Vector3d::Constant(-1e9), Eigen::Vector3d::Constant(1e9)), [&](int) { ++visits; });
  EXPECT_EQ(visits, 0);
  int calls = 0;
  EXPECT_EQ(tree.nearest(Eigen::Vector3d::Zero(), 1e30, [&](int) { return ++calls, 0.0; }), -1);
  EXPECT_EQ(calls, 0);
  // A default-constructed tree behaves the same; rebuilding a used tree empties it.
  BoundingVolumeHierarchy fresh;
  EXPECT_EQ(fresh.nearest(Eigen::Vector3d::Zero(), 1.0, [](int) { return 0.0; }), -1);
  tree.build({Box(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones())});
  EXPECT_EQ(tree.nearest(Eigen::Vector3d::Zero(), 1.0, [](int) { return 0.0; }), 0);
  tree.build({});
  EXPECT_EQ(tree.nearest(Eigen::Vector3d::Zero(), 1.0, [](int) { return 0.0; }), -1);
}

TEST(Bvh, ManyIdenticalBoxes) {
  // Equal centroids make every median split degenerate; all items must still be reachable.
  const Box b(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 0));
  std::vector<Box> boxes(33, b);
  BoundingVolumeHierarchy tree;
  tree.build(boxes);
  const std::set<int> got = tree_overlaps(tree, b);
  EXPECT_EQ(got.size(), 33u);
}
