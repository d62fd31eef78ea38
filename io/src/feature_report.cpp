// measure_quality, 1D and 0D levels: per-curve edge counts, chain topology and
// sampled distance to the curve; corners found among the corner vertices.
#include "feature_report.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <utility>

#include "mesh_labels.h"
#include "rdmesh/errors.h"
#include "rdmesh/mesh_measures.h"

namespace rdmesh::io_detail {
namespace {

const CurveInfo* find_curve(const std::vector<CurveInfo>& curves, int id) {
  auto it = std::find_if(curves.begin(), curves.end(),
                         [&](const CurveInfo& c) { return c.id.value == id; });
  return it == curves.end() ? nullptr : &*it;
}

/// Vertices of degree 1 in `edges`, sorted.
std::vector<int> chain_ends(const std::vector<std::array<int, 2>>& edges) {
  std::map<int, int> degree;
  for (const auto& e : edges) {
    ++degree[e[0]];
    ++degree[e[1]];
  }
  std::vector<int> ends;
  for (const auto& [v, d] : degree) {
    if (d == 1) ends.push_back(v);
  }
  return ends;
}

/// The shape test of CurveStats::is_chain. `corner_vertex` maps corner ids to vertices.
bool is_curve_chain(const std::vector<std::array<int, 2>>& edges, const CurveInfo* info,
                    const std::map<int, int>& corner_vertex) {
  if (info == nullptr) return is_simple_chain(edges, false) || is_simple_chain(edges, true);
  const bool loop_at_corner = !info->closed && info->start.value != 0 && info->start == info->end;
  if (!is_simple_chain(edges, info->closed || loop_at_corner)) return false;
  if (info->closed) return true;
  std::vector<int> required;
  for (CornerId c : {info->start, info->end}) {
    if (c.value == 0) continue;  // no corner named: the end is not checked
    auto it = corner_vertex.find(c.value);
    if (it == corner_vertex.end()) return false;  // the corner has no vertex
    required.push_back(it->second);
  }
  if (loop_at_corner) {
    return std::any_of(edges.begin(), edges.end(), [&](const auto& e) {
      return e[0] == required.front() || e[1] == required.front();
    });
  }
  const std::vector<int> ends = chain_ends(edges);
  return std::all_of(required.begin(), required.end(),
                     [&](int v) { return std::binary_search(ends.begin(), ends.end(), v); }) &&
         (required.size() < 2 || required[0] != required[1]);
}

/// Distance from p to the curve, or nullopt when the query fails.
std::optional<double> curve_distance(const Curve& curve, const Point3& p, double ta, double tb) {
  try {
    const double t = curve.closest(p, ta, tb);
    const double d = distance(p, curve.point(t));
    if (std::isfinite(d)) return d;
  } catch (const OracleError&) {
  }
  return std::nullopt;
}

/// Samples the curve's edges: each vertex once, then the quarter points and
/// midpoint of each distinct edge.
std::vector<Point3> curve_samples(const TetMesh& mesh,
                                  const std::vector<std::array<int, 2>>& edges) {
  std::vector<int> vertices;
  std::vector<std::pair<int, int>> unique_edges;
  for (const auto& e : edges) {
    vertices.insert(vertices.end(), e.begin(), e.end());
    unique_edges.emplace_back(std::min(e[0], e[1]), std::max(e[0], e[1]));
  }
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  std::sort(unique_edges.begin(), unique_edges.end());
  unique_edges.erase(std::unique(unique_edges.begin(), unique_edges.end()), unique_edges.end());

  std::vector<Point3> samples;
  samples.reserve(vertices.size() + 3 * unique_edges.size());
  for (int v : vertices) samples.push_back(mesh.vertices[v]);
  for (const auto& [a, b] : unique_edges) {
    const Point3 &p = mesh.vertices[a], &q = mesh.vertices[b];
    for (double s : {0.25, 0.5, 0.75}) samples.push_back((1 - s) * p + s * q);
  }
  return samples;
}

void measure_distance(const TetMesh& mesh, const std::vector<std::array<int, 2>>& edges,
                      const DomainOracle& oracle, const CurveInfo* info, CurveStats& stats) {
  const std::vector<Point3> samples = curve_samples(mesh, edges);
  std::optional<CurveInfo> oracle_info;
  if (info == nullptr) {
    try {
      for (const CurveInfo& c : oracle.curves()) {
        if (c.id == stats.id) oracle_info = c;
      }
    } catch (const OracleError&) {
    }
    if (oracle_info) info = &*oracle_info;
  }
  const Curve* curve = nullptr;
  try {
    if (info != nullptr) curve = &oracle.curve(stats.id);
  } catch (const OracleError&) {
    curve = nullptr;
  }
  if (curve == nullptr) {
    stats.projection_failures += samples.size();
    return;
  }
  for (const Point3& p : samples) {
    const std::optional<double> d = curve_distance(*curve, p, info->t_begin, info->t_end);
    if (d) {
      stats.max_distance = std::max(stats.max_distance, *d);
    } else {
      ++stats.projection_failures;
    }
  }
}

}  // namespace

void measure_features(const TetMesh& mesh, const DomainOracle* oracle, QualityReport& r) {
  std::map<int, int> corner_vertex;
  for (std::size_t c = 0; c < mesh.corner_ids.size(); ++c) {
    corner_vertex.emplace(mesh.corner_ids[c].value, mesh.corner_vertices[c]);
  }
  r.corners_expected = mesh.corners.size();
  r.corners_present = static_cast<std::size_t>(
      std::count_if(mesh.corners.begin(), mesh.corners.end(),
                    [&](const CornerInfo& c) { return corner_vertex.count(c.id.value) > 0; }));

  const std::vector<Label> curves = curve_labels(mesh);
  const auto groups = group_by_label(edge_label_values(mesh), curves);
  for (std::size_t k = 0; k < curves.size(); ++k) {
    CurveStats stats{CurveId(curves[k].id), curves[k].name};
    std::vector<std::array<int, 2>> edges;
    edges.reserve(groups[k].size());
    for (int e : groups[k]) edges.push_back(mesh.edges[e]);
    stats.edges = edges.size();
    const CurveInfo* info = find_curve(mesh.curves, curves[k].id);
    stats.is_chain = is_curve_chain(edges, info, corner_vertex);
    if (oracle != nullptr) measure_distance(mesh, edges, *oracle, info, stats);
    r.feature_max_distance = std::max(r.feature_max_distance, stats.max_distance);
    r.curves.push_back(std::move(stats));
  }
}

}  // namespace rdmesh::io_detail
