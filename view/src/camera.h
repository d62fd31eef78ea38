// Orthographic projection of the mesh into one view of the picture.
#pragma once

#include <vector>

#include "canvas.h"
#include "rdmesh/geometry.h"
#include "rdmesh/picture.h"

namespace rdmesh::view::detail {

struct Camera {
  Point3 right, up, eye;  ///< orthonormal; `eye` points from the mesh towards the viewer
  Point3 centre;          ///< the world point drawn at (px, py)
  double scale = 1;       ///< pixels per unit length
  double px = 0, py = 0;
  double depth_scale = 1;  ///< depths span about [-0.5, 0.5] over the mesh

  ScreenVertex project(const Point3& p) const {
    const Point3 d = p - centre;
    return {static_cast<float>(px + scale * dot(d, right)),
            static_cast<float>(py - scale * dot(d, up)),
            static_cast<float>(depth_scale * dot(d, eye))};
  }
  /// The same camera drawing into another panel of the same size.
  Camera moved_to(const Rect& panel) const;
};

/// p.x, p.y or p.z for axis 0, 1 or 2.
inline double coordinate(const Point3& p, int axis) {
  return axis == 0 ? p.x : axis == 1 ? p.y : p.z;
}

/// The right, up and eye directions of a view.
void view_axes(ViewDirection view, Point3& right, Point3& up, Point3& eye);

/// A camera showing all `points` inside `panel` with a margin of `margin` of
/// its size on each side.
Camera frame_points(const std::vector<Point3>& points, ViewDirection view, const Rect& panel,
                    double margin);

/// All points projected.
std::vector<ScreenVertex> project_all(const Camera& camera, const std::vector<Point3>& points);

}  // namespace rdmesh::view::detail
