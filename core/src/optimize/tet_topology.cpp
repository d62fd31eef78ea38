#include "tet_topology.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <string>
#include <utility>

#include "rdmesh/errors.h"
#include "rdmesh/parallel_for.h"
#include "tet_shape.h"

namespace rdmesh::detail {
namespace {

/// How many tets ahead the quality pass prefetches points.
constexpr std::size_t kPointLookahead = 8;

}  // namespace

bool positively_oriented(const Point3& p0, const Point3& p1, const Point3& p2, const Point3& p3) {
  using P = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
  return CGAL::orientation(P(p0.x, p0.y, p0.z), P(p1.x, p1.y, p1.z), P(p2.x, p2.y, p2.z),
                           P(p3.x, p3.y, p3.z)) == CGAL::POSITIVE;
}

double min_dihedral(const Point3& p0, const Point3& p1, const Point3& p2, const Point3& p3) {
  return cosine_to_degrees(max_dihedral_cosine(p0, p1, p2, p3));
}

bool even_order(const Tet& t, const Tet& order) {
  int pos[4];
  for (int k = 0; k < 4; ++k)
    pos[k] = static_cast<int>(std::find(t.begin(), t.end(), order[k]) - t.begin());
  int inversions = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) inversions += pos[i] > pos[j];
  return inversions % 2 == 0;
}

TetTopology::Key TetTopology::edge_key(int a, int b) {
  return {std::min(a, b), std::max(a, b), -1};
}

TetTopology::Key TetTopology::face_key(int a, int b, int c) {
  Key k{a, b, c};
  std::sort(k.begin(), k.end());
  return k;
}

TetTopology::TetTopology(const TetMesh& mesh, int threads, std::vector<double> cosines)
    : points_(mesh.vertices),
      quality_(std::move(cosines)),
      incident_(mesh.vertices.size()),
      fixed_(mesh.vertices.size(), 0) {
  const std::size_t n = mesh.tets.size();
  const bool given = !quality_.empty();  // the cosines
  if (given && quality_.size() != n)
    throw InternalError("tet topology: " + std::to_string(quality_.size()) + " cosines for " +
                        std::to_string(n) + " tetrahedra");
  tets_.reserve(n + n / 8);
  labels_.reserve(n + n / 8);
  quality_.reserve(n + n / 8);
  alive_.reserve(n + n / 8);
  tets_.assign(mesh.tets.begin(), mesh.tets.end());
  for (const SubdomainId& s : mesh.tet_subdomain) labels_.push_back(s.value);
  alive_.assign(n, 1);
  if (given) {
    // tet_quality is cosine_to_degrees of the cosine.
    parallel_for(n, threads, [&](std::size_t t) { quality_[t] = cosine_to_degrees(quality_[t]); });
  } else {
    // The qualities, each a pure function of its tet, on `threads` threads.
    quality_.resize(n);
    // The points lie all over memory: ask for those of a tet a few ahead.
    parallel_for(n, threads, [&](std::size_t t) {
      if (t + kPointLookahead < n)
        for (const int v : tets_[t + kPointLookahead]) __builtin_prefetch(&points_[v]);
      quality_[t] = tet_quality(tets_[t]);
    });
  }
  // Each vertex's list sized once (a few spare places for the flips to come):
  // growing millions of small lists by doubling costs more than the sweeps.
  // The tetrahedra in a few ranges, each counted and then written by one thread
  // at its place in the lists: every list holds its tetrahedra in order,
  // whatever the threads.
  const std::size_t parts = std::min<std::size_t>(kIncidenceParts, std::max<std::size_t>(1, n));
  const std::size_t vertices = points_.size();
  std::vector<std::vector<int>> place(parts, std::vector<int>(vertices, 0));
  const auto range = [&](std::size_t k) { return std::pair(n * k / parts, n * (k + 1) / parts); };
  parallel_tasks(parts, threads, [&](std::size_t k) {
    const auto [begin, end] = range(k);
    for (std::size_t t = begin; t < end; ++t)
      for (const int v : tets_[t]) ++place[k][v];
  });
  // On this thread: the lists come from one heap (the command's, see
  // cli/heap_setup.cpp), and two threads allocating there at once take turns
  // on its lock (8 times slower than one thread at 200 k vertices).
  for (std::size_t v = 0; v < vertices; ++v) {
    int count = 0;
    for (std::size_t k = 0; k < parts; ++k) count += std::exchange(place[k][v], count);
    incident_[v].reserve(count + kSpareIncidences);
    incident_[v].resize(count);
  }
  parallel_tasks(parts, threads, [&](std::size_t k) {
    const auto [begin, end] = range(k);
    for (std::size_t t = begin; t < end; ++t)
      for (const int v : tets_[t]) incident_[v][place[k][v]++] = static_cast<int>(t);
  });
  faces_.reserve(mesh.triangles.size());
  edges_.reserve(mesh.triangles.size() * 3 + mesh.edges.size());
  for (const auto& f : mesh.triangles) {
    faces_.push_back(face_key(f[0], f[1], f[2]));
    for (const auto& e : kTriangleEdges) edges_.push_back(edge_key(f[e[0]], f[e[1]]));
    for (const int v : f) fixed_[v] = 1;
  }
  for (const auto& e : mesh.edges) {
    edges_.push_back(edge_key(e[0], e[1]));
    fixed_[e[0]] = fixed_[e[1]] = 1;
  }
  for (std::vector<Key>* keys : {&faces_, &edges_}) {
    std::sort(keys->begin(), keys->end());
    keys->erase(std::unique(keys->begin(), keys->end()), keys->end());
  }
  for (const int v : mesh.corner_vertices) fixed_[v] = 1;
}

bool TetTopology::constrained_face(int a, int b, int c) const {
  return std::binary_search(faces_.begin(), faces_.end(), face_key(a, b, c));
}

bool TetTopology::constrained_edge(int a, int b) const {
  return std::binary_search(edges_.begin(), edges_.end(), edge_key(a, b));
}

std::vector<int> TetTopology::tets_with_edge(int a, int b) const {
  std::vector<int> out;
  for (const int t : incident_[a]) {
    const Tet& q = tets_[t];
    if (std::find(q.begin(), q.end(), b) != q.end()) out.push_back(t);
  }
  return out;
}

int TetTopology::across(int t, int a, int b, int c) const {
  for (const int u : incident_[a]) {
    if (u == t) continue;
    const Tet& q = tets_[u];
    if (std::find(q.begin(), q.end(), b) != q.end() && std::find(q.begin(), q.end(), c) != q.end())
      return u;
  }
  return -1;
}

double TetTopology::tet_quality(const Tet& t) const {
  return min_dihedral(points_[t[0]], points_[t[1]], points_[t[2]], points_[t[3]]);
}

int TetTopology::add(const Tet& t, int label) {
  const int id = static_cast<int>(tets_.size());
  tets_.push_back(t);
  labels_.push_back(label);
  quality_.push_back(tet_quality(t));
  alive_.push_back(1);
  for (const int v : t) incident_[v].push_back(id);
  return id;
}

void TetTopology::remove(int t) {
  alive_[t] = 0;
  for (const int v : tets_[t]) {
    auto& list = incident_[v];
    list.erase(std::find(list.begin(), list.end(), t));
  }
}

int TetTopology::add_vertex(const Point3& p) {
  points_.push_back(p);
  incident_.emplace_back();
  fixed_.push_back(0);
  return static_cast<int>(points_.size()) - 1;
}

void TetTopology::move(int v, const Point3& p) {
  points_[v] = p;
  for (const int t : incident_[v]) quality_[t] = tet_quality(tets_[t]);
}

void TetTopology::write_to(TetMesh& mesh) const {
  mesh.vertices = points_;
  mesh.tets.clear();
  mesh.tet_subdomain.clear();
  for (std::size_t t = 0; t < tets_.size(); ++t) {
    if (!alive_[t]) continue;
    mesh.tets.push_back(tets_[t]);
    mesh.tet_subdomain.push_back(SubdomainId{labels_[t]});
  }
}

std::vector<double> TetTopology::alive_qualities() const {
  std::vector<double> out;
  out.reserve(tets_.size());
  for (std::size_t t = 0; t < tets_.size(); ++t)
    if (alive_[t]) out.push_back(quality_[t]);
  return out;
}

}  // namespace rdmesh::detail
