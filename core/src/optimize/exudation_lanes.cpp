#include "exudation_lanes.h"

#include <algorithm>

#include "../lane_cut.h"

namespace rdmesh::detail {
namespace {

double coordinate(Vertex_handle v, int axis) {
  return detail::coordinate(to_point3(v->point()), axis);
}

}  // namespace

void assign_lanes(Triangulation& tr, const std::vector<Vertex_handle>& work, int axis) {
  std::vector<double> values;
  values.reserve(work.size());
  for (const Vertex_handle& v : work) values.push_back(coordinate(v, axis));
  assign_lanes_at(tr, axis, median(values));
}

double median(std::vector<double>& values) {
  if (values.empty()) return 0;
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

void assign_lanes_at(Triangulation& tr, int axis, double split) {
  // The refinement's cut (which reads the sides from the points), stored.
  const LaneCut cut = cut_at(tr, axis, split);
  for (auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
    v->info().lane = lane_bit(cut.holds(v, 1) ? 1 : 0);
  cut.infinite->info().lane = cut.infinite_in_lanes ? kAnyLane : kNoLane;
}

Box3 vertex_box(const Triangulation& tr) {
  Box3 box = Box3::empty();
  for (auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
    box.grow(to_point3(v->point()));
  return box;
}

std::array<int, 3> axes_by_extent(const Box3& box) {
  std::array<int, 3> axes = {0, 1, 2};
  // Stable: equal extents keep x, y, z order.
  std::stable_sort(axes.begin(), axes.end(),
                   [&](int a, int b) { return extent(box, a) > extent(box, b); });
  return axes;
}

}  // namespace rdmesh::detail
