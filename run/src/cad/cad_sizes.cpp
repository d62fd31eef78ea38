// The default sizes of a CAD run, lowered near slender parts. Without this a
// 25 mm rod of a 10 m part (bm2_ec_leverrod) or a 10 mm rod of a 267 mm
// assembly (as1-tu-203) got no cell inside it: the default size follows the
// bounding box, and rules R3-R5 are met by a few facets around the rod.
#include "cad_sizes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

namespace rdmesh::run {
namespace {

constexpr double kPerThickness = 0.5;     ///< size / thickness near a slender part
constexpr double kGrading = 0.5;          ///< size growth per unit of distance from it
constexpr double kFloor = 1.0 / 50;       ///< the sizes go no lower than this fraction of the size
constexpr double kDistancePerSize = 0.1;  ///< facet distance / facet size, as by default
constexpr double kMinSizePerThickness = 1.0 / 50;  ///< default minimum size / thinnest solid
constexpr double kMinSizeVolumeFraction = 1e-6;    ///< smaller solids do not set it

struct ThinFace {
  Box3 box;
  double size;
};

/// The limit the thin faces put on the size, per cell of a grid over the box:
/// the smallest value of size + kGrading x distance over the cell (a lower
/// bound of the limit everywhere in it), so a query costs one lookup.
class ThicknessLimit {
 public:
  ThicknessLimit(const Box3& box, double cell, const std::vector<ThinFace>& thin) : box_(box) {
    const Point3 extent = box.hi - box.lo;
    cell_ = std::max({cell, extent.x / kMaxCells, extent.y / kMaxCells, extent.z / kMaxCells});
    n_[0] = std::max(1, static_cast<int>(std::ceil(extent.x / cell_)));
    n_[1] = std::max(1, static_cast<int>(std::ceil(extent.y / cell_)));
    n_[2] = std::max(1, static_cast<int>(std::ceil(extent.z / cell_)));
    value_.assign(static_cast<std::size_t>(n_[0]) * n_[1] * n_[2],
                  std::numeric_limits<double>::infinity());
    for (int k = 0; k < n_[2]; ++k) {
      for (int j = 0; j < n_[1]; ++j) {
        for (int i = 0; i < n_[0]; ++i) {
          const Point3 lo = box.lo + Point3{i * cell_, j * cell_, k * cell_};
          const Box3 c{lo, lo + Point3{cell_, cell_, cell_}};
          double& v = value_[index(i, j, k)];
          for (const ThinFace& t : thin) v = std::min(v, t.size + kGrading * gap(c, t.box));
        }
      }
    }
  }
  double operator()(const Point3& p) const {
    auto at = [&](double x, double lo, int n) {
      return std::clamp(static_cast<int>(std::floor((x - lo) / cell_)), 0, n - 1);
    };
    return value_[index(at(p.x, box_.lo.x, n_[0]), at(p.y, box_.lo.y, n_[1]),
                        at(p.z, box_.lo.z, n_[2]))];
  }

 private:
  static constexpr double kMaxCells = 96;  ///< per axis
  std::size_t index(int i, int j, int k) const {
    return (static_cast<std::size_t>(k) * n_[1] + j) * n_[0] + i;
  }
  /// The distance between two boxes (0 when they meet).
  static double gap(const Box3& a, const Box3& b) {
    const double dx = std::max({a.lo.x - b.hi.x, 0.0, b.lo.x - a.hi.x});
    const double dy = std::max({a.lo.y - b.hi.y, 0.0, b.lo.y - a.hi.y});
    const double dz = std::max({a.lo.z - b.hi.z, 0.0, b.lo.z - a.hi.z});
    return std::sqrt(dx * dx + dy * dy + dz * dz);
  }
  Box3 box_;
  double cell_ = 1;
  int n_[3] = {1, 1, 1};
  std::vector<double> value_;
};

/// The facet distance near thin faces and in thin solids: a tenth of the size
/// the thickness asks for, never below twice the minimum size (the guard would
/// refuse the points). A solid's thickness here is 2 V / A (a plate's
/// thickness, a rod's radius): a small solid of an assembly (a nut, a washer)
/// meshed at a facet distance close to its thickness may lose half its volume
/// within that distance, and the fidelity check, whose tolerance follows the
/// facet distance, would not see it.
void follow_solid_thickness(const CadOracle& cad, Criteria& criteria, std::vector<ThinFace> thin,
                            bool min_size_too) {
  const Box3 box = cad.bounding_box();
  const double global = criteria.facet_distance(box.center());
  std::vector<double> area;
  for (const PatchInfo& p : cad.patches()) {
    const std::size_t k = static_cast<std::size_t>(p.id.value);
    if (area.size() < k) area.resize(k, 0.0);
    area[k - 1] = cad.exact_area(p.id);
  }
  double thinnest = std::numeric_limits<double>::infinity();
  const double total = cad.exact_volume();
  int solids = 0;  ///< with a volume
  for (const SubdomainInfo& s : cad.subdomains()) {
    double a = 0;
    std::optional<Box3> solid_box;
    for (const PatchInfo& p : cad.patches()) {
      if (p.side_a != s.id && p.side_b != s.id) continue;
      a += area[static_cast<std::size_t>(p.id.value) - 1];
      const Box3 b = cad.patch_box(p.id);
      if (!solid_box) solid_box = b;
      solid_box->lo = {std::min(solid_box->lo.x, b.lo.x), std::min(solid_box->lo.y, b.lo.y),
                       std::min(solid_box->lo.z, b.lo.z)};
      solid_box->hi = {std::max(solid_box->hi.x, b.hi.x), std::max(solid_box->hi.y, b.hi.y),
                       std::max(solid_box->hi.z, b.hi.z)};
    }
    if (!(a > 0) || !solid_box) continue;
    const double volume = cad.exact_volume(s.id);
    if (volume > 0) ++solids;
    const double thickness = 2 * volume / a;
    if (!(thickness > 0)) continue;
    // A solid a million times smaller than the model (a 10 mm nut in a 300 m
    // assembly whose units went wrong: occtdata_as1_motor) does not set the
    // model's minimum size: every gap of the large parts would be refined to it.
    if (volume >= kMinSizeVolumeFraction * total) thinnest = std::min(thinnest, thickness);
    const double size = kPerThickness * thickness;
    if (kDistancePerSize * size < global) thin.push_back({*solid_box, size});
  }
  if (min_size_too && thinnest < std::numeric_limits<double>::infinity()) {
    // In an assembly the gap between two touching parts thins out to nothing
    // (a ball on its race: occt_Axis_of_bearing), and refinement follows it
    // down to the minimum size over an area that grows as the minimum size
    // shrinks: 1.2M tetrahedra in 90 s at 1e-4 of the assembly's diagonal,
    // most of them in the gaps around ten balls. Each part is meshed at its
    // own scale there: the minimum size follows the thinnest part alone.
    const double own = kMinSizePerThickness * thinnest;
    criteria.min_size = solids > 1 ? own : std::min(criteria.min_size_for(box), own);
  }
  if (thin.empty()) return;
  const double h = std::min(criteria.facet_size(box.center()), criteria.cell_size(box.center()));
  auto limit = std::make_shared<const ThicknessLimit>(box, 0.25 * h, thin);
  const double floor = 2 * criteria.min_size_for(box);
  const ScalarField d = criteria.facet_distance;
  criteria.facet_distance = ScalarField::composed(
      [limit, d, floor](const Point3& p) {
        return std::min(d(p), std::max(floor, kDistancePerSize * (*limit)(p)));
      },
      {&d});
}

}  // namespace

int follow_thickness(const CadOracle& cad, Criteria& criteria, FollowedDefaults defaults) {
  std::vector<ThinFace> thin;
  const Box3 box = cad.bounding_box();
  const double h = std::min(criteria.facet_size(box.center()), criteria.cell_size(box.center()));
  for (const PatchInfo& p : cad.patches()) {
    const std::optional<double> t = cad.curved_thickness(p.id);
    if (!t) continue;
    const double size = std::max(kPerThickness * *t, kFloor * h);
    if (size < h) thin.push_back({cad.patch_box(p.id), size});
  }
  if (!thin.empty()) {
    auto limit = std::make_shared<const ThicknessLimit>(box, 0.25 * h, thin);
    auto limited = [limit](const ScalarField& f) {
      return ScalarField::composed(
          [limit, f](const Point3& p) { return std::min(f(p), (*limit)(p)); }, {&f});
    };
    criteria.facet_size = limited(criteria.facet_size);
    criteria.cell_size = limited(criteria.cell_size);
    criteria.edge_size = limited(criteria.edge_size);
  }
  if (defaults.facet_distance) follow_solid_thickness(cad, criteria, thin, defaults.min_size);
  return static_cast<int>(thin.size());
}

}  // namespace rdmesh::run
