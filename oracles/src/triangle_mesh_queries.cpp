// TriangleMeshOracle's geometric queries: locate (ray parity), intersect and
// project, on the triangle BVH with CGAL's filtered exact orientation predicate.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <cstring>

#include "rdmesh/box_tree.h"
#include "rdmesh/triangle_mesh_oracle.h"

namespace rdmesh {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

int orient(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  return static_cast<int>(CGAL::orientation(K::Point_3(a.x, a.y, a.z), K::Point_3(b.x, b.y, b.z),
                                            K::Point_3(c.x, c.y, c.z), K::Point_3(d.x, d.y, d.z)));
}

enum class Contact { kNone, kCross, kDegenerate };

/// How segment [p, q] meets triangle (a, b, c): crossing its interior
/// transversally, missing it, or touching an edge, a vertex or the plane.
/// `inclusive`: contacts with the boundary count as crossings (no kDegenerate),
/// except a segment lying in the triangle's plane (kNone).
Contact segment_triangle(const Point3& p, const Point3& q, const Point3& a, const Point3& b,
                         const Point3& c, bool inclusive) {
  const int sp = orient(a, b, c, p), sq = orient(a, b, c, q);
  if (sp == sq && sp != 0) return Contact::kNone;
  if (sp == 0 && sq == 0) return inclusive ? Contact::kNone : Contact::kDegenerate;
  const int e1 = orient(p, q, a, b), e2 = orient(p, q, b, c), e3 = orient(p, q, c, a);
  const bool neg = e1 < 0 || e2 < 0 || e3<0, pos = e1> 0 || e2 > 0 || e3 > 0;
  if (neg && pos) return Contact::kNone;
  if (inclusive) return Contact::kCross;
  if (e1 == 0 || e2 == 0 || e3 == 0 || sp == 0 || sq == 0) return Contact::kDegenerate;
  return Contact::kCross;
}

/// Ray directions: the six axis directions, each tilted by two small irrational
/// amounts, then six more tilts.
Point3 direction(int k) {
  const double s = (k & 1) ? -1.0 : 1.0;
  const int axis = (k >> 1) % 3;
  const double u = k < 6 ? 0.0137235917 : -0.0291736541, v = k < 6 ? 0.0213875519 : 0.0117352953;
  if (axis == 0) return {s, u, v};
  if (axis == 1) return {v, s, u};
  return {u, v, s};
}

}  // namespace

bool TriangleMeshOracle::ray_parity(const Point3& p, int dir, int skip, bool force,
                                    unsigned char* inside) const {
  const int count = static_cast<int>(component_volume_.size());
  std::memset(inside, 0, count);
  const Point3 d = direction(dir);
  // Leave the mesh's box along the main axis of d, with a margin.
  const int axis = (dir >> 1) % 3;
  const double pa = axis == 0 ? p.x : (axis == 1 ? p.y : p.z);
  const double lo = axis == 0 ? box_.lo.x : (axis == 1 ? box_.lo.y : box_.lo.z);
  const double hi = axis == 0 ? box_.hi.x : (axis == 1 ? box_.hi.y : box_.hi.z);
  const double length = ((dir & 1) ? pa - lo : hi - pa) + 0.01 * box_.diagonal();
  return flip_crossings(p, p + std::max(length, 0.0) * d, skip, force, inside);
}

bool TriangleMeshOracle::flip_crossings(const Point3& p, const Point3& q, int skip, bool force,
                                        unsigned char* inside) const {
  bool degenerate = false;
  const SegmentBoxTest meets(p, q);
  bvh_->traverse([&](const Box3& b) { return meets(b); },
                 [&](int t) {
                   const int c = triangle_component_[t];
                   if (c == skip) return true;
                   const auto& tri = mesh_.triangles[t];
                   const Contact contact =
                       segment_triangle(p, q, mesh_.points[tri[0]], mesh_.points[tri[1]],
                                        mesh_.points[tri[2]], force);
                   if (contact == Contact::kDegenerate) degenerate = true;
                   if (contact == Contact::kCross) inside[c] ^= 1;
                   return !degenerate;
                 });
  return !degenerate;
}

int TriangleMeshOracle::innermost(const unsigned char* inside) const {
  int best = -1;
  const int count = static_cast<int>(component_volume_.size());
  for (int c = 0; c < count; ++c) {
    if (inside[c] && (best < 0 || component_depth_[c] > component_depth_[best])) best = c;
  }
  return best;
}

Located TriangleMeshOracle::locate(const Point3& p, const std::optional<LocateHint>& hint) const {
  if (options_.surface_only || !mesh_box_.contains(p)) return {kOutside, std::nullopt};
  if (hint) {
    const std::optional<SubdomainId> walked = walk(p, *hint);
    if (walked) return {*walked, std::nullopt};
  }
  unsigned char inside[kMaxComponents];
  // First the direction that leaves the box soonest.
  const double gaps[6] = {mesh_box_.hi.x - p.x, p.x - mesh_box_.lo.x, mesh_box_.hi.y - p.y,
                          p.y - mesh_box_.lo.y, mesh_box_.hi.z - p.z, p.z - mesh_box_.lo.z};
  int first = 0;
  for (int k = 1; k < 6; ++k) {
    if (gaps[k] < gaps[first]) first = k;
  }
  bool ok = false;
  for (int i = 0; i < 12 && !ok; ++i)
    ok = ray_parity(p, i == 0 ? first : (first + i) % 12, -1, false, inside);
  if (!ok) ray_parity(p, first, -1, true, inside);
  return {SubdomainId(innermost(inside) + 1), std::nullopt};
}

std::optional<SubdomainId> TriangleMeshOracle::walk(const Point3& p, const LocateHint& hint) const {
  const int count = static_cast<int>(component_volume_.size());
  if (!mesh_box_.contains(hint.point) || hint.label.value < 0 || hint.label.value > count) {
    return std::nullopt;
  }
  // Components never touch, so the ones containing the hint's point are its
  // innermost one and that one's ancestors; each crossing of [p, hint] flips one.
  unsigned char inside[kMaxComponents];
  std::memset(inside, 0, count);
  for (int c = hint.label.value - 1; c >= 0; c = component_parent_[c]) inside[c] = 1;
  if (!flip_crossings(p, hint.point, -1, false, inside))
    return std::nullopt;  // an edge or a vertex
  return SubdomainId(innermost(inside) + 1);
}

std::optional<SurfaceHit> TriangleMeshOracle::intersect(const Point3& a, const Point3& b) const {
  double best_t = 2;
  int best = -1;
  const SegmentBoxTest meets(a, b);
  bvh_->traverse([&](const Box3& box) { return meets(box); },
                 [&](int t) {
                   const auto& tri = mesh_.triangles[t];
                   const Point3 &p = mesh_.points[tri[0]], &q = mesh_.points[tri[1]],
                                &r = mesh_.points[tri[2]];
                   if (segment_triangle(a, b, p, q, r, true) != Contact::kCross) return true;
                   const Point3 n = cross(q - p, r - p);
                   const double da = dot(n, a - p), db = dot(n, b - p);
                   double s = da == db ? 0.0 : da / (da - db);
                   s = std::clamp(s, 0.0, 1.0);
                   if (s < best_t || (s == best_t && t < best)) {
                     best_t = s;
                     best = t;
                   }
                   return true;
                 });
  if (best < 0) return std::nullopt;
  return SurfaceHit{a + best_t * (b - a), triangle_patch_[best]};
}

std::optional<Point3> TriangleMeshOracle::project(const Point3& x, PatchId patch) const {
  if (patch.value < 1 || patch.value > static_cast<int>(patch_infos_.size())) return std::nullopt;
  double best = HUGE_VAL;
  Point3 result;
  bvh_->nearest([&](const Box3& box) { return squared_distance(box, x); },
                [&](int t, double& bound) {
                  if (triangle_patch_[t] != patch) return;
                  const auto& tri = mesh_.triangles[t];
                  const Point3 y = closest_on_triangle(x, mesh_.points[tri[0]],
                                                       mesh_.points[tri[1]], mesh_.points[tri[2]]);
                  const double d2 = squared_norm(y - x);
                  if (d2 < bound) {
                    bound = d2;
                    result = y;
                  }
                },
                best);
  if (best == HUGE_VAL) return std::nullopt;
  return result;
}

}  // namespace rdmesh
