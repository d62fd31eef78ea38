#include "camera.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rdmesh::view::detail {

Camera Camera::moved_to(const Rect& panel) const {
  Camera c = *this;
  c.px = panel.x0 + 0.5 * panel.width();
  c.py = panel.y0 + 0.5 * panel.height();
  return c;
}

void view_axes(ViewDirection view, Point3& right, Point3& up, Point3& eye) {
  const Point3 z{0, 0, 1};
  switch (view) {
    case ViewDirection::kX:
      eye = {1, 0, 0};
      break;
    case ViewDirection::kY:
      eye = {0, -1, 0};
      break;
    case ViewDirection::kZ:
      eye = z;
      right = {1, 0, 0};
      up = {0, 1, 0};
      return;
    case ViewDirection::kIso:
      eye = (1 / std::sqrt(3.0)) * Point3{1, -1, 1};
      break;
  }
  right = cross(z, eye);
  right = (1 / norm(right)) * right;
  up = cross(eye, right);
}

Camera frame_points(const std::vector<Point3>& points, ViewDirection view, const Rect& panel,
                    double margin) {
  Camera c;
  view_axes(view, c.right, c.up, c.eye);
  constexpr double kInf = std::numeric_limits<double>::infinity();
  double lo[3] = {kInf, kInf, kInf}, hi[3] = {-kInf, -kInf, -kInf};
  for (const Point3& p : points) {
    const double d[3] = {dot(p, c.right), dot(p, c.up), dot(p, c.eye)};
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], d[k]);
      hi[k] = std::max(hi[k], d[k]);
    }
  }
  if (points.empty()) lo[0] = lo[1] = lo[2] = hi[0] = hi[1] = hi[2] = 0;
  const double mid[3] = {0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2])};
  c.centre = mid[0] * c.right + mid[1] * c.up + mid[2] * c.eye;
  const double extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  const double w = hi[0] - lo[0], h = hi[1] - lo[1], big = std::max(w, h);
  const double usable_w = panel.width() * (1 - 2 * margin),
               usable_h = panel.height() * (1 - 2 * margin);
  c.scale = big > 0
                ? std::min(usable_w / std::max(w, 1e-9 * big), usable_h / std::max(h, 1e-9 * big))
                : 1;
  c.depth_scale = extent > 0 ? 1 / extent : 1;
  return c.moved_to(panel);
}

std::vector<ScreenVertex> project_all(const Camera& camera, const std::vector<Point3>& points) {
  std::vector<ScreenVertex> out;
  out.reserve(points.size());
  for (const Point3& p : points) out.push_back(camera.project(p));
  return out;
}

}  // namespace rdmesh::view::detail
