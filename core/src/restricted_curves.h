// Private to core/: the restricted Delaunay triangulations D|L_j of the curves.
//
// Samples of a curve are kept sorted by parameter. Between two consecutive
// samples p, q the arc carries the restricted Delaunay ball of the edge pq:
// its center c is the point of the arc equidistant to p and q (a point of the
// Voronoi facet V(p, q) on L_j), its radius |c - p|. The edge pq belongs to
// D|L_j while that ball is empty; a vertex entering the ball means the Voronoi
// cell of a vertex not on the arc reaches the curve (rule R1). A closed curve
// carries its first sample twice, at t_begin and at t_end, so that every arc
// is a pair of consecutive map entries.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "optimize/chain_edges.h"
#include "rdmesh/curve.h"
#include "rdmesh/oracle.h"
#include "triangulation_types.h"

namespace rdmesh::detail {

/// The sample at parameter t and the arc from it to the next sample.
struct CurveSample {
  Vertex_handle vertex;  ///< valid during refinement
  Point3 position{};     ///< the sample point (stays valid after exudation)
  Point3 center{};       ///< restricted Delaunay ball of the arc to the next sample
  double t_center = 0;   ///< parameter of the center
  double squared_radius = 0;
};

struct CurveState {
  CurveInfo info;
  const Curve* curve = nullptr;
  std::map<double, CurveSample> samples;  ///< by parameter

  using Arc = std::map<double, CurveSample>::iterator;  ///< arc = sample and its successor
  bool has_next(Arc a) const { return std::next(a) != samples.end(); }
};

/// An arc of curve `curve` starting at parameter `t`, with the vertices it
/// joined when it was queued (to recognise a stale entry).
struct ArcRef {
  int curve;  ///< index into the curve table (id - 1)
  double t;
  Vertex_handle a, b;
};

/// D|L: the samples of every curve, in parameter order, with the balls of the
/// arcs between them, and the corners. The levels of level_curves.h fill it.
class RestrictedCurves {
 public:
  /// Reads the oracle's corners and curves (OracleError unless their ids are 1..n in order).
  explicit RestrictedCurves(const DomainOracle& oracle);

  std::vector<CurveState>& curves() { return curves_; }  ///< index = CurveId - 1
  const std::vector<CurveState>& curves() const { return curves_; }
  const std::vector<CornerInfo>& corners() const { return corners_; }  ///< index = CornerId - 1
  /// The patches each corner bounds, and each curve (index = id - 1).
  std::vector<std::vector<PatchId>> corner_patches() const;
  std::vector<std::vector<PatchId>> curve_patches() const;

  /// The arcs having vertex v as an endpoint.
  void arcs_of(Vertex_handle v, std::vector<std::pair<int, CurveState::Arc>>& out);
  /// The live arc an entry refers to, or nullopt when it was split meanwhile.
  std::optional<CurveState::Arc> find_arc(const ArcRef& ref);
  /// The edges of D|L: consecutive samples of every curve.
  ChainEdges chain_edges() const;
  /// The feature v lies on (feature_name()), or "volume".
  std::string describe(const VertexInfo& v) const;

 private:
  std::vector<CurveState> curves_;
  std::vector<CornerInfo> corners_;
};

}  // namespace rdmesh::detail
