// Private to core/: the CGAL triangulation D(P) and the per-simplex data of
// the restricted complex. Only the core's .cpp files include this header, so
// CGAL's templates are instantiated in a handful of translation units.
#pragma once

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Regular_triangulation_cell_base_3.h>
#include <CGAL/Regular_triangulation_vertex_base_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <array>
#include <cstdint>
#include <memory>

#include "rdmesh/debug_assert.h"
#include "rdmesh/geometry.h"

namespace rdmesh::detail {

/// Dimension of the input feature a sample point lies on (RR-7912: F_0..F_3).
enum class FeatureDim : std::int8_t { kCorner = 0, kCurve = 1, kPatch = 2, kVolume = 3 };

/// The input feature a vertex was inserted on: a corner, a curve or a patch,
/// or none (a volume point). Each id is read through the accessor of its
/// dimension, which checks it (RDMESH_DEBUG_ASSERT): a curve id is never read
/// as a patch id. Eight bytes, as the int and the dimension it replaces.
class FeatureRef {
 public:
  /// A volume point: on no feature.
  constexpr FeatureRef() = default;
  constexpr explicit FeatureRef(CornerId q) : dim_(FeatureDim::kCorner), id_(q.value) {}
  constexpr explicit FeatureRef(CurveId c) : dim_(FeatureDim::kCurve), id_(c.value) {}
  constexpr explicit FeatureRef(PatchId p) : dim_(FeatureDim::kPatch), id_(p.value) {}

  FeatureDim dim() const { return dim_; }
  CornerId corner() const {
    RDMESH_DEBUG_ASSERT(dim_ == FeatureDim::kCorner, "a corner id read from another feature");
    return CornerId{id_};
  }
  CurveId curve() const {
    RDMESH_DEBUG_ASSERT(dim_ == FeatureDim::kCurve, "a curve id read from another feature");
    return CurveId{id_};
  }
  PatchId patch() const {
    RDMESH_DEBUG_ASSERT(dim_ == FeatureDim::kPatch, "a patch id read from another feature");
    return PatchId{id_};
  }

 private:
  FeatureDim dim_ = FeatureDim::kVolume;
  int id_ = 0;  ///< the CornerId / CurveId / PatchId value for dim_ 0 / 1 / 2
};

/// Per vertex: on which feature it was inserted (corners first, refine-edge on
/// a curve, refine-facet on a patch, refine-tet in the volume). Rules R1 and
/// R3 read it.
struct VertexInfo {
  FeatureRef feature;
  double t = 0.0;  ///< curve parameter when on a curve
  int index = -1;  ///< scratch: output index during extraction
  /// Scratch of exudation: the lanes (a bit each, exudation_lanes.h) whose part
  /// of space holds the vertex; it fits in the padding after `index`.
  std::uint8_t lane = 0;
  double ball_weight = 0.0;  ///< squared radius of its protecting ball (0: none)

  FeatureDim dim() const { return feature.dim(); }
};
static_assert(sizeof(VertexInfo) <= 32, "a vertex's info stays 32 bytes");

/// CellInfo::facet_patch of a facet that is not in D|S (patch ids start at 1).
inline constexpr PatchId kNotRestricted{0};

/// The centers of the surface Delaunay balls of a cell's four facets, stored
/// out of line: only cells with a restricted facet (a few percent of them,
/// along the surface) need them, and held inline they were 96 of a cell's 256
/// bytes. Storage appears on the first set() and is freed with the cell; a
/// read never creates it (a read of a cell without storage sees the origin;
/// facet_patch says which entries mean something). Writes go through set()
/// alone, so a read through a non-const cell cannot allocate: exudation once
/// gave nearly every cell 112 bytes of storage that way, a quarter of the peak.
class SurfaceCenters {
 public:
  SurfaceCenters() = default;
  SurfaceCenters(const SurfaceCenters& o)
      : centers_(o.centers_ ? std::make_unique<std::array<Point3, 4>>(*o.centers_) : nullptr) {}
  SurfaceCenters(SurfaceCenters&&) noexcept = default;
  SurfaceCenters& operator=(const SurfaceCenters& o) {
    if (this != &o) *this = SurfaceCenters(o);
    return *this;
  }
  SurfaceCenters& operator=(SurfaceCenters&&) noexcept = default;

  const Point3& operator[](int i) const { return centers_ ? (*centers_)[i] : kNone; }
  void set(int i, const Point3& center) {
    if (!centers_) centers_ = std::make_unique<std::array<Point3, 4>>();
    (*centers_)[i] = center;
  }
  /// Whether any entry was ever set (tests: storage only where restricted).
  bool has_storage() const { return centers_ != nullptr; }

 private:
  static inline const Point3 kNone{};
  std::unique_ptr<std::array<Point3, 4>> centers_;
};

/// Per cell: its Delaunay ball, its label in D|O, and the restricted status
/// of its four facets in D|S. A facet is seen from both incident cells and
/// both copies are always written together (see RestrictedComplex::update_facet).
struct CellInfo {
  /// Creation stamp, unique over the run; 0 for a cell that was destroyed or
  /// not yet initialized. Queue entries carry the stamp they saw (CGAL
  /// reuses the memory of destroyed cells).
  std::uint32_t stamp = 0;
  int label = 0;  ///< SubdomainId of the circumcenter (0 outside, infinite cells)
  /// Refinement's ball of the cell, finite cells only. Exudation, after
  /// refinement, neither reads nor maintains it (refinement never resumes).
  Point3 circumcenter;
  union {
    double squared_radius = 0.0;  ///< refinement: of the ball above
    /// Exudation: cosine of the smallest dihedral angle for a domain cell
    /// (label != 0, finite), -infinity for the others. The exuder sets it on
    /// every cell before it reads one, and on every cell it creates.
    double shape_cosine;
  };
  std::array<PatchId, 4> facet_patch{};  ///< patch of facet i, or kNotRestricted
  SurfaceCenters surface_center;         ///< center of facet i's surface Delaunay ball
  /// A crossing of facet `crossing_facet`'s dual edge found while labeling this
  /// cell from the neighbor with stamp `crossing_with` (held in facet_patch and
  /// surface_center until update_facet() takes it); -1: none.
  std::int8_t crossing_facet = -1;
  std::uint32_t crossing_with = 0;
};

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

/// Regular_triangulation_cell_base_3's container of hidden points. The refiner
/// discards hidden points (Discard_hidden_points only ever asks this container
/// for its end(), an empty range), so instead of CGAL's default std::list, 24
/// bytes constructed and destroyed with every cell, an empty range of none.
struct NoHiddenPoints {
  using iterator = Kernel::Weighted_point_3*;
  using const_iterator = const Kernel::Weighted_point_3*;
  iterator begin() { return nullptr; }
  iterator end() { return nullptr; }
  const_iterator begin() const { return nullptr; }
  const_iterator end() const { return nullptr; }
};

using Vb =
    CGAL::Triangulation_vertex_base_with_info_3<VertexInfo, Kernel,
                                                CGAL::Regular_triangulation_vertex_base_3<Kernel>>;
using Cb = CGAL::Triangulation_cell_base_with_info_3<
    CellInfo, Kernel,
    CGAL::Regular_triangulation_cell_base_3<Kernel, CGAL::Triangulation_cell_base_3<Kernel>,
                                            CGAL::Discard_hidden_points, NoHiddenPoints>>;
using Tds = CGAL::Triangulation_data_structure_3<Vb, Cb, CGAL::Sequential_tag>;
using Triangulation = CGAL::Regular_triangulation_3<Kernel, Tds>;
using Cell_handle = Triangulation::Cell_handle;
using Vertex_handle = Triangulation::Vertex_handle;
using Weighted_point = Triangulation::Weighted_point;

inline Point3 to_point3(const Weighted_point& p) { return {p.x(), p.y(), p.z()}; }
inline Weighted_point to_weighted(const Point3& p) {
  return Weighted_point(Kernel::Point_3(p.x, p.y, p.z), 0.0);
}

}  // namespace rdmesh::detail
