// Exact geometric checks of triangle meshes (CGAL's filtered exact predicates):
// coordinates and degenerate triangles (validate_soup), self-intersections.
#include "rdmesh/triangle_mesh_check.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <cmath>
#include <sstream>

#include "rdmesh/box_tree.h"
#include "rdmesh/errors.h"

namespace rdmesh {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using P = K::Point_3;

P cgal(const Point3& p) { return {p.x, p.y, p.z}; }

std::string str(const Point3& p) {
  std::ostringstream s;
  s.precision(17);
  s << "(" << p.x << " " << p.y << " " << p.z << ")";
  return s.str();
}

/// Whether triangles t and u (with at most one shared edge) meet beyond what they share.
bool intersect(const TriangleSoup& soup, const std::array<int, 3>& t, const std::array<int, 3>& u) {
  int shared = 0, ti[3] = {-1, -1, -1}, ui[3] = {-1, -1, -1};  // ti[i]: index in u of t[i]
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (t[i] == u[j]) {
        ti[i] = j;
        ui[j] = i;
        ++shared;
      }
    }
  }
  auto pt = [&](int v) { return cgal(soup.points[v]); };
  const K::Triangle_3 tt(pt(t[0]), pt(t[1]), pt(t[2])), tu(pt(u[0]), pt(u[1]), pt(u[2]));
  if (shared == 0) return CGAL::do_intersect(tt, tu);
  if (shared == 3) return true;
  if (shared == 2) {  // folded onto each other: coplanar with the free corners on one side
    int a = -1, b = -1, c = -1, d = -1;
    for (int i = 0; i < 3; ++i) {
      if (ti[i] < 0)
        c = t[i];
      else
        (a < 0 ? a : b) = t[i];
      if (ui[i] < 0) d = u[i];
    }
    const P pa = pt(a), pb = pt(b), pc = pt(c), pd = pt(d);
    return CGAL::coplanar(pa, pb, pc, pd) &&
           CGAL::coplanar_orientation(pa, pb, pc, pd) == CGAL::POSITIVE;
  }
  // One shared vertex: the opposite edge of either triangle meets the other one.
  int it = 0, iu = 0;
  while (ti[it] < 0) ++it;
  while (ui[iu] < 0) ++iu;
  const K::Segment_3 st(pt(t[(it + 1) % 3]), pt(t[(it + 2) % 3]));
  const K::Segment_3 su(pt(u[(iu + 1) % 3]), pt(u[(iu + 2) % 3]));
  return CGAL::do_intersect(st, tu) || CGAL::do_intersect(su, tt);
}

}  // namespace

void validate_soup(const TriangleSoup& soup, const std::string& file) {
  if (soup.triangles.empty()) throw InputError(file, "no triangle");
  for (std::size_t i = 0; i < soup.points.size(); ++i) {
    const Point3& p = soup.points[i];
    for (double c : {p.x, p.y, p.z}) {
      if (!std::isfinite(c))
        throw InputError(file, "vertex " + std::to_string(i) + " has a non-finite coordinate");
      if (std::abs(c) > 1e100)
        throw InputError(
            file, "vertex " + std::to_string(i) + " has a coordinate above 1e100: " + str(p));
    }
  }
  const int n = static_cast<int>(soup.points.size());
  for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
    const auto& tri = soup.triangles[t];
    for (int v : tri) {
      if (v < 0 || v >= n) {
        throw InputError(file, "triangle " + std::to_string(t) + ": vertex index " +
                                   std::to_string(v) + " out of range [0, " + std::to_string(n) +
                                   ")");
      }
    }
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) {
      throw InputError(file, "degenerate triangle " + std::to_string(t) + ": a repeated vertex " +
                                 "(after merging duplicates)");
    }
    const Point3 &a = soup.points[tri[0]], &b = soup.points[tri[1]], &c = soup.points[tri[2]];
    if (CGAL::collinear(cgal(a), cgal(b), cgal(c))) {
      throw InputError(file, "degenerate triangle " + std::to_string(t) + ": collinear corners " +
                                 str(a) + " " + str(b) + " " + str(c));
    }
  }
}

void check_self_intersections(const TriangleSoup& soup, const std::string& file) {
  const BoxTree bvh(soup.points, soup.triangles);
  const int n = static_cast<int>(soup.triangles.size());
  for (int t = 0; t < n; ++t) {
    const auto& tri = soup.triangles[t];
    const Box3 box = Box3::around({soup.points[tri[0]], soup.points[tri[1]], soup.points[tri[2]]});
    int bad = -1;
    bvh.traverse([&](const Box3& b) { return boxes_overlap(b, box); },
                 [&](int u) {
                   if (u > t && intersect(soup, tri, soup.triangles[u])) bad = u;
                   return bad < 0;
                 });
    if (bad >= 0) {
      const auto& o = soup.triangles[bad];
      throw InputError(file, "self-intersecting: triangles " + std::to_string(t) + " " +
                                 str(soup.points[tri[0]]) + " " + str(soup.points[tri[1]]) + " " +
                                 str(soup.points[tri[2]]) + " and " + std::to_string(bad) + " " +
                                 str(soup.points[o[0]]) + " " + str(soup.points[o[1]]) + " " +
                                 str(soup.points[o[2]]) + " intersect");
    }
  }
}

}  // namespace rdmesh
