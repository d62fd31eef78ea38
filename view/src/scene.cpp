#include "scene.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "exposed_faces.h"

namespace rdmesh::view::detail {
namespace {

/// Brightness of a face with normal `n` (any length, either side) under a light
/// a little above and left of the viewer.
double lighting(const Camera& camera, const Point3& n) {
  const Point3 light = camera.eye + 0.45 * camera.up - 0.3 * camera.right;
  const double len = norm(n) * norm(light);
  const double cosine = len > 0 ? std::abs(dot(n, light)) / len : 0;
  return 0.45 + 0.55 * cosine;
}

/// Draws the sharp curves (both ends kept by `keep`) and, if `corners`, the corners.
template <class Keep>
void draw_features(Canvas& canvas, const std::vector<ScreenVertex>& screen, const ViewMesh& mesh,
                   const Strokes& strokes, bool corners, Keep keep) {
  constexpr float kBias = 0.01f;
  for (const auto& e : mesh.edges) {
    if (keep(e[0]) && keep(e[1]))
      canvas.draw_line(screen[e[0]], screen[e[1]], strokes.feature, kInk, kBias);
  }
  if (!corners) return;
  for (int v : mesh.corners) {
    canvas.draw_dot(screen[v], strokes.corner + strokes.feature * 0.5f, kBackground, kBias);
    canvas.draw_dot(screen[v], strokes.corner, kInk, 2 * kBias);
  }
}

void draw_triangles(Canvas& canvas, const Camera& camera, const std::vector<ScreenVertex>& screen,
                    const ViewMesh& mesh, const Surface& surface, const Strokes& strokes,
                    const std::vector<char>* kept_points) {
  const LabelRanks ranks(*surface.labels);
  for (std::size_t t = 0; t < surface.triangles->size(); ++t) {
    const auto& tri = (*surface.triangles)[t];
    if (kept_points &&
        !((*kept_points)[tri[0]] && (*kept_points)[tri[1]] && (*kept_points)[tri[2]]))
      continue;
    const Point3& a = mesh.points[tri[0]];
    const double light = lighting(camera, cross(mesh.points[tri[1]] - a, mesh.points[tri[2]] - a));
    const Rgb base = label_colour(ranks.rank((*surface.labels)[t]));
    canvas.fill_triangle(screen[tri[0]], screen[tri[1]], screen[tri[2]], shade(base, light),
                         shade(base, 0.72 * light), strokes.element_edge);
  }
}

/// The faces of the kept tetrahedra that no other kept one shares and that face
/// the viewer, coloured by subdomain (`worst` ones unshaded in kHighlight),
/// with their sides.
void draw_tet_faces(Canvas& canvas, const Camera& camera, const std::vector<ScreenVertex>& screen,
                    const ViewMesh& mesh, const std::vector<char>& kept_tets,
                    const std::vector<char>& worst, const Strokes& strokes) {
  const LabelRanks ranks(mesh.tet_labels);
  for (const TetFace& f : exposed_faces(mesh, kept_tets)) {
    const auto& tet = mesh.tets[f.tet];
    const int k = static_cast<int>(f.local), i = (k + 1) % 4, j = (k + 2) % 4, l = (k + 3) % 4;
    const Point3& pi = mesh.points[tet[i]];
    Point3 n = cross(mesh.points[tet[j]] - pi, mesh.points[tet[l]] - pi);
    const double away = -dot(n, mesh.points[tet[k]] - pi);  // > 0: n points out of the tetrahedron
    if (away < 0) n = -1.0 * n;
    if (away != 0 && dot(n, camera.eye) <= 0) continue;  // back face
    const Rgb base = worst[f.tet] ? kHighlight : label_colour(ranks.rank(mesh.tet_labels[f.tet]));
    const double light = lighting(camera, n);
    canvas.fill_triangle(screen[tet[i]], screen[tet[j]], screen[tet[l]],
                         worst[f.tet] ? kHighlight : shade(base, light), shade(base, 0.55 * light),
                         strokes.element_edge);
  }
}

}  // namespace

Surface boundary_surface(const ViewMesh& mesh) {
  Surface s;
  if (!mesh.triangles.empty() || mesh.tets.empty()) {
    s.triangles = &mesh.triangles;
    s.labels = &mesh.triangle_labels;
    return s;
  }
  for (const TetFace& f : exposed_faces(mesh, {})) {
    const auto& tet = mesh.tets[f.tet];
    s.derived.push_back({tet[(f.local + 1) % 4], tet[(f.local + 2) % 4], tet[(f.local + 3) % 4]});
    s.derived_labels.push_back(mesh.tet_labels[f.tet]);
  }
  s.triangles = &s.derived;
  s.labels = &s.derived_labels;
  s.from_tets = true;
  return s;
}

void draw_surface_view(Canvas& canvas, const Camera& camera, const ViewMesh& mesh,
                       const Surface& surface, const Strokes& strokes) {
  const std::vector<ScreenVertex> screen = project_all(camera, mesh.points);
  draw_triangles(canvas, camera, screen, mesh, surface, strokes, nullptr);
  draw_features(canvas, screen, mesh, strokes, true, [](int) { return true; });
}

void draw_cut_view(Canvas& canvas, const Camera& camera, const ViewMesh& mesh,
                   const Surface& surface, const CutPlane& cut, const TetQuality& quality,
                   double sliver_angle, const Strokes& strokes) {
  const std::vector<ScreenVertex> screen = project_all(camera, mesh.points);
  const int side = coordinate(camera.eye, cut.axis) >= 0 ? 1 : -1;
  auto behind = [&](double x) { return (x - cut.offset) * side <= 0; };
  std::vector<char> kept(mesh.points.size());
  for (std::size_t i = 0; i < mesh.points.size(); ++i) {
    kept[i] = behind(coordinate(mesh.points[i], cut.axis));
  }
  if (mesh.tets.empty()) {
    draw_triangles(canvas, camera, screen, mesh, surface, strokes, &kept);
    draw_features(canvas, screen, mesh, strokes, false, [&](int v) { return kept[v] != 0; });
    return;
  }
  std::vector<char> kept_tets(mesh.tets.size());
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    double centroid = 0;
    for (int v : mesh.tets[t]) centroid += 0.25 * coordinate(mesh.points[v], cut.axis);
    kept_tets[t] = behind(centroid);
  }
  std::vector<char> worst(mesh.tets.size());
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) worst[t] = quality.min_angle[t] < sliver_angle;
  draw_tet_faces(canvas, camera, screen, mesh, kept_tets, worst, strokes);
  draw_features(canvas, screen, mesh, strokes, false, [&](int v) { return kept[v] != 0; });
  // Rings on top mark every highlighted tetrahedron behind the cut, also the
  // hidden ones and those too small to see.
  constexpr float kOnTop = 2;  // depths lie within [-0.5, 0.5]
  const float radius = 1.5f * strokes.corner, hole = radius - 1.5f * strokes.element_edge;
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    if (!kept_tets[t] || !worst[t]) continue;
    Point3 centroid;
    for (int v : mesh.tets[t]) centroid = centroid + 0.25 * mesh.points[v];
    canvas.draw_dot(camera.project(centroid), radius, kHighlight, kOnTop, hole);
  }
}

}  // namespace rdmesh::view::detail
