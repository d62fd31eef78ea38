// The polyhedral oracle: a domain bounded by closed triangle meshes, with its
// sharp edges as curves (RR-7912's own setting: an edge is sharp when the normals
// of its two triangles turn by more than the feature angle, 60 degrees by default).
//
// Subdomains. Each closed component (edge-connected set of triangles) bounds a
// region; components may be side by side or nested (they may not touch: that
// is a self-intersection). Subdomain k+1 is the inside of component k (in order
// of its first triangle) minus the insides of the components nested in it, so
// a ball inside a ball gives a shell (1) and a core (2). locate() counts, with
// exact orientation predicates, the crossings of a ray with each component
// (parity says inside or not) and returns the innermost component containing
// the point; a ray through an edge or a vertex is retried in another direction.
//
// Patches are the regions of triangles connected across non-sharp edges, ids
// 1..m in order of their first triangle. A patch lies on one component, between
// its subdomain and the enclosing one (or kOutside).
//
// Curves and corners. Corners are the vertices with a number of sharp edges
// other than 0 and 2, and the vertices where two sharp edges turn by more than
// the feature angle (a kink: curves are smooth), ids in vertex order. Curves are the chains of
// sharp edges between corners (open, in order of their start corner, then of the first edge around
// it) and the loops of sharp edges without corner (closed, after the open ones, in order of their
// first vertex); each is a PolylineCurve through the mesh vertices (parameter = arc length) whose
// patches are those on both sides. A sharp edge inside a patch (a crease that fades out) gives a
// curve whose two sides are that one patch.
//
// Queries. intersect() returns the crossing closest to a (exact predicates
// decide which triangles the segment meets, the point is computed in double);
// a segment whose ends locate() differently always gets a hit. Both, and
// project(), walk a bounding-volume hierarchy without heap allocation, are const
// and thread-safe.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "rdmesh/feature_table.h"
#include "rdmesh/oracle.h"
#include "rdmesh/polyline_curve.h"
#include "rdmesh/triangle_mesh_io.h"

namespace rdmesh {

class BoxTree;

/// Options of TriangleMeshOracle.
struct TriangleMeshOptions {
  /// An edge is sharp when the normals of its two triangles make an angle above this (degrees).
  double feature_angle_degrees = 60;
  /// Reject self-intersecting inputs (costs a BVH pass with exact predicates).
  bool check_self_intersections = true;
  /// A surface without a volume: open (or closed) components are accepted,
  /// there is no subdomain (locate() is kOutside everywhere), every patch has
  /// kOutside on both sides, and the border edges of open components are
  /// sharp (they become curves, so the mesh's border follows them). For
  /// MeshOptions::surface_only.
  bool surface_only = false;
};

class TriangleMeshOracle final : public DomainOracle {
 public:
  /// At most this many closed components (locate keeps one parity byte per component on the stack).
  static constexpr int kMaxComponents = 256;

  /// Builds the oracle from a soup (validate_soup'ed or not: it is validated
  /// again). Throws InputError "FILE: problem" (`file` may be empty) for every
  /// problem of validate_soup, orient_triangle_mesh (closed required),
  /// check_self_intersections, a feature angle outside [0, 180] and more than
  /// kMaxComponents components.
  TriangleMeshOracle(TriangleSoup soup, const std::string& file = "",
                     TriangleMeshOptions options = {});
  ~TriangleMeshOracle() override;
  TriangleMeshOracle(const TriangleMeshOracle&) = delete;
  TriangleMeshOracle& operator=(const TriangleMeshOracle&) = delete;

  /// Reads `path` (read_triangle_mesh) and builds the oracle.
  static std::unique_ptr<TriangleMeshOracle> from_file(const std::string& path,
                                                       TriangleMeshOptions options = {});

  /// The mesh's box, enlarged by 1% of its diagonal on every side.
  Box3 bounding_box() const override { return box_; }
  /// Without a hint, the parity of the crossings of a ray from p with each
  /// component. With one, the parity of the crossings of [p, hint] flips the
  /// components holding the hint's point (no crossing is returned); a segment
  /// through an edge or a vertex falls back to the rays.
  Located locate(const Point3& p,
                 const std::optional<LocateHint>& hint = std::nullopt) const override;
  std::optional<SurfaceHit> intersect(const Point3& a, const Point3& b) const override;
  std::vector<SubdomainInfo> subdomains() const override { return subdomain_infos_; }
  std::vector<PatchInfo> patches() const override { return patch_infos_; }
  /// Centroids of up to 8 triangles of the patch spread over its triangle list
  /// (at least 3 points: more inside a single triangle for tiny patches).
  std::vector<Point3> initial_points(PatchId patch) const override {
    return features_.initial_points(patch);
  }
  /// The closest point of the patch's triangles (exact up to rounding); nullopt
  /// for an unknown patch.
  std::optional<Point3> project(const Point3& p, PatchId patch) const override;
  /// Discrete, per patch: at each vertex of the patch's triangles, the largest
  /// |2 n . (q - v)| / |q - v|^2 over its neighbours q in the patch (the
  /// curvature of the circle through q tangent to the plane of normal n at v;
  /// n the angle-weighted normal of the vertex's triangles in the patch, so
  /// exact for vertices on a sphere or a cylinder), interpolated linearly over
  /// the patch's triangle nearest p. nullopt for an unknown patch.
  std::optional<double> curvature(const Point3& p, PatchId patch) const override;
  /// 1e-10 times the mesh's box diagonal.
  double tolerance() const override { return tolerance_; }
  std::vector<CornerInfo> corners() const override { return features_.corners(); }
  std::vector<CurveInfo> curves() const override { return features_.curves(); }
  const Curve& curve(CurveId id) const override { return features_.curve(id); }

  /// The oriented mesh (normals out of each closed component, duplicates merged).
  const TriangleSoup& mesh() const { return mesh_; }
  /// The patch of each triangle of mesh().
  const std::vector<PatchId>& triangle_patches() const { return triangle_patch_; }
  /// Volume of the domain (the sum of the subdomains' volumes).
  double volume() const { return volume_; }
  /// Number of sharp edges found.
  int sharp_edge_count() const { return sharp_edge_count_; }

 private:
  /// Sharp flags per triangle edge (edge k from corner k to corner k + 1).
  using EdgeFlags = std::vector<std::array<bool, 3>>;
  void build_subdomains(int component_count);
  void build_patches(const std::vector<std::array<int, 3>>& neighbors, const EdgeFlags& sharp);
  void build_curvature();  // triangle_mesh_curvature.cpp
  /// Initial points on the triangles `tris` of a patch (see initial_points()).
  std::vector<Point3> points_on(const std::vector<int>& tris) const;
  // triangle_mesh_features.cpp
  EdgeFlags sharp_edges(const std::vector<std::array<int, 3>>& neighbors) const;
  void build_features(const std::vector<std::array<int, 3>>& neighbors, const EdgeFlags& sharp);
  /// Parity of the crossings of the ray from p along direction number `dir`
  /// with each component, in `inside` (one byte per component), ignoring
  /// component `skip`; false when the ray meets an edge or a vertex (or p lies
  /// on a triangle), unless `force` (then such contacts count half-open).
  bool ray_parity(const Point3& p, int dir, int skip, bool force, unsigned char* inside) const;
  /// Flips inside[c] for each crossing of [p, q] with component c (same rules).
  bool flip_crossings(const Point3& p, const Point3& q, int skip, bool force,
                      unsigned char* inside) const;
  /// The label of p from the hint's by the crossings of [p, hint.point];
  /// nullopt when the segment meets an edge or a vertex or the hint is unusable.
  std::optional<SubdomainId> walk(const Point3& p, const LocateHint& hint) const;
  /// The deepest component flagged in `inside`, -1 for none.
  int innermost(const unsigned char* inside) const;

  TriangleSoup mesh_;
  TriangleMeshOptions options_;
  std::string file_;
  Box3 box_;
  Box3 mesh_box_;  // the mesh's own bounding box
  double tolerance_ = 0;
  double volume_ = 0;
  std::unique_ptr<BoxTree> bvh_;
  std::vector<int> triangle_component_;
  std::vector<PatchId> triangle_patch_;
  std::vector<int> component_parent_;  // enclosing component, -1 for none
  std::vector<int> component_depth_;
  std::vector<double> component_volume_;
  std::vector<SubdomainInfo> subdomain_infos_;
  std::vector<PatchInfo> patch_infos_;
  std::vector<std::vector<int>> patch_triangles_;        // indexed by patch id - 1
  std::vector<std::array<double, 3>> corner_curvature_;  // per triangle corner, within its patch
  int sharp_edge_count_ = 0;
  FeatureTable<PolylineCurve> features_;  // sharp curves, corners, initial points
};

}  // namespace rdmesh
