// Internal to core/: sizes that hold on pieces of the domain (sampled patches
// and curves) and grow linearly with the distance to them, folded into the
// criteria's size fields by a minimum. Shared by the entity sizes and the
// curvature sizes (rdmesh/entity_sizes.h, rdmesh/curvature_sizes.h).
#pragma once

#include <array>
#include <memory>
#include <utility>
#include <vector>

#include "rdmesh/box_tree.h"
#include "rdmesh/criteria.h"
#include "rdmesh/curvature_sizes.h"
#include "rdmesh/geometry.h"
#include "rdmesh/oracle.h"
#include "rdmesh/tet_mesh.h"

namespace rdmesh::detail {

/// A piecewise-linear stand-in of a part of an entity: triangles, segments
/// (third index -1) and points (both others equal, third -1).
struct Pieces {
  std::vector<Point3> points;
  std::vector<std::array<int, 3>> items;
};

/// One set of pieces of one size: h + slope x distance to the pieces.
class GradedSize {
 public:
  GradedSize(Pieces pieces, double size, double slope);
  double size() const { return size_; }
  /// min(bound, h + slope x distance): the search stops where the pieces can
  /// no longer lower `bound`.
  double below(const Point3& p, double bound) const;

 private:
  Pieces pieces_;
  BoxTree bvh_;
  double size_, slope_;
};

/// Every graded set, smallest size first (it lowers the bound soonest).
class GradedField {
 public:
  explicit GradedField(double slope) : slope_(slope) {}
  double slope() const { return slope_; }
  /// Pieces that all take `size`.
  void add(Pieces pieces, double size);
  /// Pieces with a size each (sizes[i] for pieces.items[i]): grouped into
  /// classes of sizes within a factor 1.1, each at its smallest size.
  void add_sized(const Pieces& pieces, const std::vector<double>& sizes);
  bool empty() const { return sets_.empty(); }
  double below(const Point3& p, double bound) const;

 private:
  double slope_;
  std::vector<std::unique_ptr<GradedSize>> sets_;
};

/// base(p) lowered by `near` and, inside subdomain id, to its size (one
/// DomainOracle::locate per evaluation when `inside` is not empty).
ScalarField lowered(const ScalarField& base, std::shared_ptr<const GradedField> near,
                    std::shared_ptr<const std::vector<std::pair<int, double>>> inside,
                    const DomainOracle* oracle);

/// A first, surface-only mesh at the criteria's sizes, whose triangles sample the patches.
TetMesh sampling_surface(const DomainOracle& oracle, const Criteria& criteria);

/// Adds to `field` the curvature sizes for `per_turn` elements per turn
/// (rdmesh/curvature_sizes.h), sampling the patches on `surface` and
/// dropping what does not go below `criteria`'s sizes (curvature_sizes.cpp).
CurvatureStats add_curvature_pieces(const DomainOracle& oracle, const TetMesh& surface,
                                    const Criteria& criteria, double per_turn, GradedField& field);

}  // namespace rdmesh::detail
