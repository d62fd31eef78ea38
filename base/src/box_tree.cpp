// The BVH of rdmesh/box_tree.h: construction and its small geometric helpers.
#include "rdmesh/box_tree.h"

#include <algorithm>
#include <cmath>

namespace rdmesh {
namespace {

double axis(const Point3& p, int k) { return k == 0 ? p.x : (k == 1 ? p.y : p.z); }

double half_area(const Box3& b) {
  const Point3 e = b.hi - b.lo;
  return e.x * e.y + e.y * e.z + e.z * e.x;
}

}  // namespace

BoxTree::BoxTree(const std::vector<Point3>& points,
                 const std::vector<std::array<int, 3>>& triangles) {
  const int n = static_cast<int>(triangles.size());
  if (n == 0) return;
  std::vector<Box3> boxes(n);
  std::vector<Point3> centroids(n);
  for (int t = 0; t < n; ++t) {
    boxes[t] =
        Box3::around({points[triangles[t][0]], points[triangles[t][1]], points[triangles[t][2]]});
    centroids[t] =
        (1.0 / 3) * (points[triangles[t][0]] + points[triangles[t][1]] + points[triangles[t][2]]);
  }
  build_all(boxes, centroids);
}

BoxTree::BoxTree(const std::vector<Box3>& boxes) {
  std::vector<Point3> centres(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) centres[i] = boxes[i].center();
  build_all(boxes, centres);
}

void BoxTree::build_all(const std::vector<Box3>& boxes, const std::vector<Point3>& centres) {
  const int n = static_cast<int>(boxes.size());
  if (n == 0) return;
  order_.resize(n);
  for (int t = 0; t < n; ++t) order_[t] = t;
  nodes_.reserve(2 * (n / kLeafSize + 1));
  build(0, n, 0, boxes, centres);
}

int BoxTree::build(int begin, int end, int depth, const std::vector<Box3>& boxes,
                   const std::vector<Point3>& centroids) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.push_back({});
  Box3 box = Box3::empty(), cbox = Box3::empty();
  for (int i = begin; i < end; ++i) {
    box.grow(boxes[order_[i]].lo);
    box.grow(boxes[order_[i]].hi);
    cbox.grow(centroids[order_[i]]);
  }
  nodes_[index].box = box;
  if (end - begin <= kLeafSize || depth >= kMaxDepth - 1) {
    nodes_[index].first = begin;
    nodes_[index].count = end - begin;
    return index;
  }
  const Point3 extent = cbox.hi - cbox.lo;
  const int k = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
  const int mid = sah_split(begin, end, k, axis(cbox.lo, k), axis(extent, k), boxes, centroids);
  build(begin, mid, depth + 1, boxes, centroids);
  const int right = build(mid, end, depth + 1, boxes, centroids);
  nodes_[index].first = right;
  nodes_[index].count = 0;
  return index;
}

int BoxTree::sah_split(int begin, int end, int k, double lo, double width,
                       const std::vector<Box3>& boxes, const std::vector<Point3>& centroids) {
  // Binned surface area heuristic along axis k: the cut between bins that
  // minimizes area(left) * count(left) + area(right) * count(right), so that a
  // query's segment enters few boxes; the median when the centres coincide.
  constexpr int kBins = 16;
  const int mid = begin + (end - begin) / 2;
  auto by_axis = [&](int a, int b) {
    const double ca = axis(centroids[a], k), cb = axis(centroids[b], k);
    return ca < cb || (ca == cb && a < b);
  };
  auto bin_of = [&](int item) {
    const int b = static_cast<int>(kBins * (axis(centroids[item], k) - lo) / width);
    return std::clamp(b, 0, kBins - 1);
  };
  auto median = [&] {
    std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end, by_axis);
    return mid;
  };
  if (!(width > 0)) return median();
  Box3 bin_box[kBins];
  int bin_count[kBins] = {};
  for (Box3& b : bin_box) b = Box3::empty();
  for (int i = begin; i < end; ++i) {
    const int b = bin_of(order_[i]);
    ++bin_count[b];
    bin_box[b].grow(boxes[order_[i]].lo);
    bin_box[b].grow(boxes[order_[i]].hi);
  }
  double right_area[kBins];
  int right_count[kBins];
  Box3 acc = Box3::empty();
  int count = 0;
  for (int b = kBins - 1; b > 0; --b) {
    if (bin_count[b] > 0) acc.grow(bin_box[b].lo), acc.grow(bin_box[b].hi);
    count += bin_count[b];
    right_area[b] = count > 0 ? half_area(acc) : 0;
    right_count[b] = count;
  }
  acc = Box3::empty();
  count = 0;
  double best = HUGE_VAL;
  int best_cut = -1;  // left: bins [0, best_cut)
  for (int b = 1; b < kBins; ++b) {
    if (bin_count[b - 1] > 0) acc.grow(bin_box[b - 1].lo), acc.grow(bin_box[b - 1].hi);
    count += bin_count[b - 1];
    if (count == 0 || right_count[b] == 0) continue;
    const double cost = half_area(acc) * count + right_area[b] * right_count[b];
    if (cost < best) best = cost, best_cut = b;
  }
  if (best_cut < 0) return median();
  const auto split = std::partition(order_.begin() + begin, order_.begin() + end,
                                    [&](int item) { return bin_of(item) < best_cut; });
  return static_cast<int>(split - order_.begin());
}

SegmentBoxTest::SegmentBoxTest(const Point3& a, const Point3& b) {
  const double pa[3] = {a.x, a.y, a.z}, pb[3] = {b.x, b.y, b.z};
  for (int k = 0; k < 3; ++k) {
    const double d = pb[k] - pa[k];
    a_[k] = pa[k];
    inv_[k] = 1.0 / d;
    flat_[k] = !std::isfinite(inv_[k]);  // d = 0, or so small that its reciprocal overflows
    if (flat_[k]) inv_[k] = 0.0;
  }
}

bool SegmentBoxTest::operator()(const Box3& box) const {
  double t0 = 0, t1 = 1;
  const double lo[3] = {box.lo.x, box.lo.y, box.lo.z}, hi[3] = {box.hi.x, box.hi.y, box.hi.z};
  for (int k = 0; k < 3; ++k) {
    // The margin also covers the rounding of the reciprocal (a few ulps).
    const double margin = 1e-12 * (std::abs(lo[k]) + std::abs(hi[k]) + (hi[k] - lo[k]));
    const double l = lo[k] - margin, h = hi[k] + margin;
    if (flat_[k]) {
      if (a_[k] < l || a_[k] > h) return false;
      continue;
    }
    double ta = (l - a_[k]) * inv_[k], tb = (h - a_[k]) * inv_[k];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1 * (1 + 1e-12) + 1e-300) return false;
  }
  return true;
}

bool segment_meets_box(const Point3& a, const Point3& b, const Box3& box) {
  return SegmentBoxTest(a, b)(box);
}

Point3 closest_on_triangle(const Point3& x, const Point3& p, const Point3& q, const Point3& r) {
  // Voronoi regions of the vertices, then of the edges, then the face.
  const Point3 ab = q - p, ac = r - p, ap = x - p;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return p;
  const Point3 bp = x - q;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return q;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return p + (d1 / (d1 - d3)) * ab;
  const Point3 cp = x - r;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return r;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return p + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    return q + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (r - q);
  }
  const double denom = 1 / (va + vb + vc);
  return p + (vb * denom) * ab + (vc * denom) * ac;
}

}  // namespace rdmesh
