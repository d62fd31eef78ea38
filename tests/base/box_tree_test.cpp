// The box tree (BVH) against brute force: traverse() visits exactly the items whose
// boxes a query box overlaps, nearest() finds the closest triangle, and the
// segment-box test agrees with sampling the segment.
#include "rdmesh/box_tree.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <vector>

namespace rdmesh {
namespace {

struct Soup {
  std::vector<Point3> points;
  std::vector<std::array<int, 3>> triangles;
};

Soup random_soup(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1), small(-0.1, 0.1);
  Soup s;
  for (int i = 0; i < n; ++i) {
    const Point3 c{u(rng), u(rng), u(rng)};
    for (int k = 0; k < 3; ++k) s.points.push_back(c + Point3{small(rng), small(rng), small(rng)});
    s.triangles.push_back({3 * i, 3 * i + 1, 3 * i + 2});
  }
  return s;
}

Box3 box_of(const Soup& s, int t) {
  const auto& tri = s.triangles[t];
  return Box3::around({s.points[tri[0]], s.points[tri[1]], s.points[tri[2]]});
}

TEST(Box3, AroundPointsIsTheirComponentwiseRange) {
  const Box3 b = Box3::around({{1, -2, 3}, {0, 5, -1}, {2, 0, 0}});
  EXPECT_EQ(b.lo, (Point3{0, -2, -1}));
  EXPECT_EQ(b.hi, (Point3{2, 5, 3}));
  EXPECT_FALSE(Box3::empty().contains({0, 0, 0}));
  Box3 one = Box3::empty();
  one.grow({1, 2, 3});
  EXPECT_TRUE(one.contains({1, 2, 3}));
  EXPECT_EQ(one.lo, one.hi);
}

TEST(BoxTree, TraverseVisitsExactlyTheOverlappingItems) {
  const Soup s = random_soup(500, 7);
  const BoxTree tree(s.points, s.triangles);
  ASSERT_FALSE(tree.empty());
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int q = 0; q < 50; ++q) {
    const Point3 c{u(rng), u(rng), u(rng)};
    const Box3 query{c - Point3{0.2, 0.2, 0.2}, c + Point3{0.2, 0.2, 0.2}};
    std::set<int> found, expected;
    tree.traverse([&](const Box3& b) { return boxes_overlap(b, query); },
                  [&](int t) {
                    if (boxes_overlap(box_of(s, t), query)) {
                      EXPECT_TRUE(found.insert(t).second);
                    }
                    return true;
                  });
    for (int t = 0; t < static_cast<int>(s.triangles.size()); ++t) {
      if (boxes_overlap(box_of(s, t), query)) expected.insert(t);
    }
    EXPECT_EQ(found, expected);
  }
}

TEST(BoxTree, NearestFindsTheClosestTriangle) {
  const Soup s = random_soup(300, 11);
  const BoxTree tree(s.points, s.triangles);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  auto dist2 = [&](const Point3& x, int t) {
    const auto& tri = s.triangles[t];
    return squared_norm(
        x - closest_on_triangle(x, s.points[tri[0]], s.points[tri[1]], s.points[tri[2]]));
  };
  for (int q = 0; q < 100; ++q) {
    const Point3 x{u(rng), u(rng), u(rng)};
    double best = INFINITY;
    tree.nearest([&](const Box3& b) { return squared_distance(b, x); },
                 [&](int t, double& b) { b = std::min(b, dist2(x, t)); }, best);
    double brute = INFINITY;
    for (int t = 0; t < static_cast<int>(s.triangles.size()); ++t)
      brute = std::min(brute, dist2(x, t));
    EXPECT_EQ(best, brute);
  }
}

TEST(BoxTree, SegmentTestAgreesWithSamplesOfTheSegment) {
  const Box3 box{{0, 0, 0}, {1, 1, 1}};
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1, 2);
  int hits = 0;
  for (int q = 0; q < 2000; ++q) {
    const Point3 a{u(rng), u(rng), u(rng)}, b{u(rng), u(rng), u(rng)};
    bool sampled = false;
    for (int k = 0; k <= 1000 && !sampled; ++k) {
      const Point3 p = a + (k / 1000.0) * (b - a);
      sampled = p.x >= 0 && p.x <= 1 && p.y >= 0 && p.y <= 1 && p.z >= 0 && p.z <= 1;
    }
    // A sampled hit is a hit; the slab test may only add hits that graze the box.
    if (sampled) {
      EXPECT_TRUE(segment_meets_box(a, b, box));
    }
    hits += sampled;
  }
  EXPECT_GT(hits, 100);
  EXPECT_FALSE(segment_meets_box({2, 2, 2}, {3, 3, 3}, box));
  EXPECT_TRUE(segment_meets_box({0.5, 0.5, -1}, {0.5, 0.5, 2}, box));  // flat in x and y
}

}  // namespace
}  // namespace rdmesh
