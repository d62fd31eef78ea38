// measure_quality: per-tet quality figures, per-label counts and volumes,
// boundary topology and the sampled distance of boundary triangles to their patch.
#include "rdmesh/quality_report.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include "feature_report.h"
#include "mesh_labels.h"
#include "rdmesh/errors.h"
#include "rdmesh/parallel_for.h"

namespace rdmesh {
namespace {

using io_detail::Label;

/// How many tets ahead measure_tets prefetches vertices.
constexpr std::size_t kVertexLookahead = 8;

/// The quality figures of a run of tets, folded into `r` by measure_tets.
struct TetFigures {
  double min_dihedral = std::numeric_limits<double>::infinity();
  double max_dihedral = 0;
  double max_radius_edge = 0;
  std::array<std::size_t, 36> histogram{};
  std::size_t inverted = 0;
  std::vector<SubdomainStats> subdomains;  ///< tets and volumes only
};

/// Folds the quality figures of every tet into `r` (and the per-subdomain
/// volumes): each chunk of tets on one of `threads` threads, the chunks' sums
/// added in chunk order (the same bits for any thread count).
void measure_tets(const TetMesh& mesh, const std::vector<Label>& subdomains, int threads,
                  QualityReport& r) {
  std::vector<TetFigures> chunks(chunk_count(mesh.tets.size()));
  for_chunks(mesh.tets.size(), threads, [&](std::size_t k, std::size_t begin, std::size_t end) {
    // Summed here and moved into place once: neighbouring chunks' sums share
    // cache lines, and two threads writing them at every tet ran slower than one.
    TetFigures f;
    f.subdomains.resize(subdomains.size());
    for (std::size_t t = begin; t < end; ++t) {
      // The vertices lie all over memory: ask for those of a tet a few ahead.
      if (t + kVertexLookahead < end)
        for (const int v : mesh.tets[t + kVertexLookahead]) __builtin_prefetch(&mesh.vertices[v]);
      const auto& tet = mesh.tets[t];
      const Point3 &a = mesh.vertices[tet[0]], &b = mesh.vertices[tet[1]],
                   &c = mesh.vertices[tet[2]], &d = mesh.vertices[tet[3]];
      const auto [lo, hi] = dihedral_extremes_deg(a, b, c, d);
      f.min_dihedral = std::min(f.min_dihedral, lo);
      f.max_dihedral = std::max(f.max_dihedral, hi);
      ++f.histogram[static_cast<std::size_t>(std::clamp(lo / 5.0, 0.0, 35.0))];
      f.max_radius_edge = std::max(f.max_radius_edge, radius_edge_ratio(a, b, c, d));
      const double volume = signed_volume(a, b, c, d);
      if (volume <= 0) ++f.inverted;
      const int id = mesh.tet_subdomain[t].value;
      auto it = std::lower_bound(subdomains.begin(), subdomains.end(), id,
                                 [](const Label& l, int v) { return l.id < v; });
      SubdomainStats& s = f.subdomains[static_cast<std::size_t>(it - subdomains.begin())];
      ++s.tets;
      s.volume += volume;
    }
    chunks[k] = std::move(f);
  });
  r.min_dihedral_deg = mesh.tets.empty() ? 0 : std::numeric_limits<double>::infinity();
  r.max_dihedral_deg = 0;
  for (const TetFigures& f : chunks) {
    r.min_dihedral_deg = std::min(r.min_dihedral_deg, f.min_dihedral);
    r.max_dihedral_deg = std::max(r.max_dihedral_deg, f.max_dihedral);
    r.max_radius_edge = std::max(r.max_radius_edge, f.max_radius_edge);
    for (std::size_t i = 0; i < f.histogram.size(); ++i) r.dihedral_histogram[i] += f.histogram[i];
    r.inverted_tets += f.inverted;
    for (std::size_t i = 0; i < f.subdomains.size(); ++i) {
      r.subdomains[i].tets += f.subdomains[i].tets;
      r.subdomains[i].volume += f.subdomains[i].volume;
    }
  }
}

/// Distance from p to its projection on `patch`; updates `max_distance` or counts a failure.
void sample(const DomainOracle& oracle, PatchId patch, const Point3& p, PatchStats& stats) {
  std::optional<Point3> q;
  try {
    q = oracle.project(p, patch);
  } catch (const OracleError&) {
    q.reset();
  }
  if (!q) {
    ++stats.projection_failures;
    return;
  }
  stats.max_distance = std::max(stats.max_distance, distance(p, *q));
}

/// Samples the vertices, edge midpoints and centroids of `triangles` (each shared
/// vertex and edge once) against the patch of `stats`.
void measure_distance(const TetMesh& mesh, const std::vector<std::array<int, 3>>& triangles,
                      const DomainOracle& oracle, PatchStats& stats) {
  std::vector<int> vertices;
  std::vector<std::uint64_t> edges;
  for (const auto& t : triangles) {
    for (int i = 0; i < 3; ++i) {
      vertices.push_back(t[i]);
      const int a = std::min(t[i], t[(i + 1) % 3]), b = std::max(t[i], t[(i + 1) % 3]);
      edges.push_back((static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b));
    }
  }
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());

  const std::vector<Point3>& v = mesh.vertices;
  for (int i : vertices) sample(oracle, stats.id, v[i], stats);
  for (std::uint64_t e : edges) {
    const auto a = static_cast<std::size_t>(e >> 32), b = static_cast<std::size_t>(e & 0xffffffffu);
    sample(oracle, stats.id, 0.5 * (v[a] + v[b]), stats);
  }
  for (const auto& t : triangles) {
    sample(oracle, stats.id, (1.0 / 3.0) * (v[t[0]] + v[t[1]] + v[t[2]]), stats);
  }
}

void measure_patches(const TetMesh& mesh, const std::vector<Label>& patches,
                     const DomainOracle* oracle, QualityReport& r) {
  const auto groups = io_detail::group_by_label(io_detail::triangle_label_values(mesh), patches);
  for (std::size_t k = 0; k < patches.size(); ++k) {
    PatchStats& stats = r.patches[k];
    std::vector<std::array<int, 3>> triangles;
    triangles.reserve(groups[k].size());
    for (int f : groups[k]) triangles.push_back(mesh.triangles[f]);
    stats.triangles = triangles.size();
    for (const auto& t : triangles) {
      const Point3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
      stats.area += 0.5 * norm(cross(b - a, c - a));
    }
    stats.euler_characteristic = euler_characteristic(triangles);
    if (oracle != nullptr) measure_distance(mesh, triangles, *oracle, stats);
    r.projection_failures += stats.projection_failures;
    r.boundary_max_distance = std::max(r.boundary_max_distance, stats.max_distance);
  }
  r.boundary_euler_characteristic = euler_characteristic(mesh.triangles);
}

}  // namespace

QualityReport measure_quality(const TetMesh& mesh, const DomainOracle* oracle, int threads) {
  io_detail::check_mesh(mesh);
  QualityReport r;
  r.vertices = mesh.vertices.size();
  r.tets = mesh.tets.size();
  r.triangles = mesh.triangles.size();

  const std::vector<Label> subdomains = io_detail::subdomain_labels(mesh);
  for (const Label& l : subdomains) r.subdomains.push_back({SubdomainId(l.id), l.name});
  measure_tets(mesh, subdomains, threads, r);

  const std::vector<Label> patches = io_detail::patch_labels(mesh);
  for (const Label& l : patches) r.patches.push_back({PatchId(l.id), l.name});
  measure_patches(mesh, patches, oracle, r);
  io_detail::measure_features(mesh, oracle, r);
  return r;
}

}  // namespace rdmesh
