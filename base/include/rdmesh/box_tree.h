// A bounding-volume hierarchy over items given by their boxes (triangles of a
// point set, or any boxes), shared by the triangle-mesh and CAD oracles and by
// core's graded size field; not part of the oracle interface.
//
// Nodes are stored depth-first in one array; a leaf holds up to kLeafSize
// consecutive entries of `order()` (item indices). Built once by splits along
// the longest axis of the items' centre points, where the binned surface area
// heuristic puts them (the median when the centres coincide); queries are const,
// allocation-free (fixed traversal stack) and thread-safe.
#pragma once

#include <array>
#include <vector>

#include "rdmesh/geometry.h"

namespace rdmesh {

class BoxTree {
 public:
  struct Node {
    Box3 box;
    int first = 0;  ///< leaf: first entry of order(); inner node: index of the right child
    int count = 0;  ///< leaf: number of triangles; inner node: 0 (left child is next)
  };
  static constexpr int kLeafSize = 4;
  static constexpr int kMaxDepth = 64;

  BoxTree() = default;
  /// Over triangles of `points`, each bounded by its own box.
  BoxTree(const std::vector<Point3>& points, const std::vector<std::array<int, 3>>& triangles);
  /// Over items given by their boxes (item i has box boxes[i], e.g. a triangle's box
  /// inflated by how far the surface it stands for may deviate from it).
  explicit BoxTree(const std::vector<Box3>& boxes);

  const std::vector<Node>& nodes() const { return nodes_; }
  const std::vector<int>& order() const { return order_; }
  bool empty() const { return nodes_.empty(); }

  /// Calls leaf(triangle) for every triangle of every leaf whose box passes
  /// `enter(box)`; stops early when leaf returns false.
  template <class Enter, class Leaf>
  void traverse(Enter&& enter, Leaf&& leaf) const {
    if (nodes_.empty()) return;
    int stack[kMaxDepth + 2];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& n = nodes_[stack[--top]];
      if (!enter(n.box)) continue;
      if (n.count > 0) {
        for (int i = n.first; i < n.first + n.count; ++i) {
          if (!leaf(order_[i])) return;
        }
      } else {
        const int self = static_cast<int>(&n - nodes_.data());
        stack[top++] = n.first;
        stack[top++] = self + 1;
      }
    }
  }

  /// Nearest-first traversal: `lower(box)` is a lower bound of the distance of
  /// anything in box, `leaf(triangle, best)` may lower `best`; boxes whose bound
  /// is not below best are skipped.
  template <class Lower, class Leaf>
  void nearest(Lower&& lower, Leaf&& leaf, double& best) const {
    if (nodes_.empty()) return;
    struct Entry {
      int node;
      double bound;
    };
    Entry stack[kMaxDepth + 2];
    int top = 0;
    stack[top++] = {0, lower(nodes_[0].box)};
    while (top > 0) {
      const Entry e = stack[--top];
      if (e.bound >= best) continue;
      const Node& n = nodes_[e.node];
      if (n.count > 0) {
        for (int i = n.first; i < n.first + n.count; ++i) leaf(order_[i], best);
        continue;
      }
      const int l = e.node + 1, r = n.first;
      const double bl = lower(nodes_[l].box), br = lower(nodes_[r].box);
      if (bl < br) {  // push the farther child first
        stack[top++] = {r, br};
        stack[top++] = {l, bl};
      } else {
        stack[top++] = {l, bl};
        stack[top++] = {r, br};
      }
    }
  }

 private:
  void build_all(const std::vector<Box3>& boxes, const std::vector<Point3>& centres);
  int build(int begin, int end, int depth, const std::vector<Box3>& boxes,
            const std::vector<Point3>& centres);
  /// Reorders order_[begin, end) into two non-empty runs along axis k (centres
  /// spread over [lo, lo + width]); returns where the second run starts.
  int sah_split(int begin, int end, int k, double lo, double width, const std::vector<Box3>& boxes,
                const std::vector<Point3>& centroids);

  std::vector<Node> nodes_;
  std::vector<int> order_;
};

/// Whether boxes a and b overlap (closed boxes).
inline bool boxes_overlap(const Box3& a, const Box3& b) {
  return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y &&
         a.lo.z <= b.hi.z && b.lo.z <= a.hi.z;
}

/// Squared distance from p to box b (0 inside).
inline double squared_distance(const Box3& b, const Point3& p) {
  auto d = [](double v, double lo, double hi) { return v < lo ? lo - v : (v > hi ? v - hi : 0.0); };
  const double dx = d(p.x, b.lo.x, b.hi.x), dy = d(p.y, b.lo.y, b.hi.y),
               dz = d(p.z, b.lo.z, b.hi.z);
  return dx * dx + dy * dy + dz * dz;
}

/// Whether segment [a, b] meets a box (slab test, with a relative margin). One
/// segment is tested against many boxes in a tree walk: the reciprocal of its
/// direction is computed once, so each box costs multiplications only.
class SegmentBoxTest {
 public:
  SegmentBoxTest(const Point3& a, const Point3& b);
  bool operator()(const Box3& box) const;

 private:
  double a_[3], inv_[3];
  bool flat_[3];  ///< no extent along that axis: a point test there
};

/// SegmentBoxTest(a, b)(box), for a single box.
bool segment_meets_box(const Point3& a, const Point3& b, const Box3& box);

/// The point of triangle (p, q, r) closest to x.
Point3 closest_on_triangle(const Point3& x, const Point3& p, const Point3& q, const Point3& r);

}  // namespace rdmesh
