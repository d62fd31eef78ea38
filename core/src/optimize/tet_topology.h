// Private to core/: a tetrahedral mesh that local improvement can change,
// with what must not change. Tetrahedra are numbered as they are created
// (removed ones stay dead), vertices keep their indices. A tetrahedron's
// vertex order is always positive (CGAL's orientation of its four points).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "rdmesh/geometry.h"
#include "rdmesh/tet_mesh.h"

namespace rdmesh::detail {

using Tet = std::array<int, 4>;

/// True when (p0, p1, p2, p3) is positively oriented by CGAL's exact predicate
/// (det(p1 - p0, p2 - p0, p3 - p0) > 0).
bool positively_oriented(const Point3& p0, const Point3& p1, const Point3& p2, const Point3& p3);

/// The smallest dihedral angle of a tetrahedron, in degrees (0 when flat).
double min_dihedral(const Point3& p0, const Point3& p1, const Point3& p2, const Point3& p3);

/// True when (t[i]) for the vertices `order` (a permutation of t's vertices)
/// is an even permutation of t: the order is positive when t is.
bool even_order(const Tet& t, const Tet& order);

class TetTopology {
 public:
  /// Copies the tetrahedra of `mesh`; its triangles, feature edges and corners are the constraints.
  /// `threads`: for the qualities of the tetrahedra and the vertices' lists
  /// (0: all cores); the topology is the same for any number. `cosines`:
  /// when not empty, the max_dihedral_cosine of each of mesh.tets, known
  /// beforehand (Refiner::extract_mesh): the qualities are their angles,
  /// the same bits as tet_quality, in that vector's memory.
  explicit TetTopology(const TetMesh& mesh, int threads = 1, std::vector<double> cosines = {});

  std::size_t size() const { return tets_.size(); }  ///< tetrahedra ever created
  bool alive(int t) const { return alive_[t]; }
  const Tet& tet(int t) const { return tets_[t]; }
  int label(int t) const { return labels_[t]; }
  double quality(int t) const { return quality_[t]; }  ///< smallest dihedral angle, degrees
  const Point3& point(int v) const { return points_[v]; }
  int vertex_count() const { return static_cast<int>(points_.size()); }
  const std::vector<int>& tets_of(int v) const { return incident_[v]; }  ///< alive ones

  /// A vertex on a triangle, a feature edge or a corner: it never moves.
  bool fixed(int v) const { return fixed_[v]; }
  bool constrained_face(int a, int b, int c) const;
  bool constrained_edge(int a, int b) const;

  /// Alive tetrahedra holding both a and b (in the order of a's list).
  std::vector<int> tets_with_edge(int a, int b) const;
  /// The alive tetrahedron other than `t` holding face (a, b, c); -1 when none.
  int across(int t, int a, int b, int c) const;

  /// Adds a positively oriented tetrahedron; returns its number.
  int add(const Tet& t, int label);
  void remove(int t);
  /// Adds a free vertex (in no tetrahedron yet); returns its index.
  int add_vertex(const Point3& p);
  /// Moves vertex v (not fixed) and updates the qualities of its tetrahedra.
  void move(int v, const Point3& p);
  double tet_quality(const Tet& t) const;

  /// Writes the alive tetrahedra (in creation order) and the vertex positions back.
  void write_to(TetMesh& mesh) const;
  /// The qualities of the alive tetrahedra, in write_to()'s order.
  std::vector<double> alive_qualities() const;

 private:
  using Key = std::array<int, 3>;  ///< sorted vertices; an edge's third is -1
  /// Places reserved in each vertex's list of tetrahedra beyond its first count.
  static constexpr int kSpareIncidences = 4;
  /// Ranges of tetrahedra the vertices' lists are built from, in parallel
  /// (a count per vertex each: few, whatever the threads).
  static constexpr std::size_t kIncidenceParts = 4;
  static Key edge_key(int a, int b);
  static Key face_key(int a, int b, int c);

  std::vector<Point3> points_;
  std::vector<Tet> tets_;
  std::vector<int> labels_;
  std::vector<double> quality_;
  std::vector<char> alive_;
  std::vector<std::vector<int>> incident_;
  std::vector<char> fixed_;
  /// The constraints, sorted (built once, then only searched: a sort of the
  /// keys took a fifth of the time a hash set took to fill).
  std::vector<Key> faces_, edges_;
};

}  // namespace rdmesh::detail
