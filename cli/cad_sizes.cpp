// The default sizes of a CAD run, lowered near slender parts. Without this a
// 25 mm rod of a 10 m part (bm2_ec_leverrod) or a 10 mm rod of a 267 mm
// assembly (as1-tu-203) got no cell inside it: the default size follows the
// bounding box, and rules R3-R5 are met by a few facets around the rod.
#include "cad_sizes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

namespace rdmesh::cli {
namespace {

constexpr double kPerThickness = 0.5;  ///< size / thickness near a slender part
constexpr double kGrading = 0.5;       ///< size growth per unit of distance from it
constexpr double kFloor = 1.0 / 50;    ///< the sizes go no lower than this fraction of the size

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

}  // namespace

int follow_thickness(const CadOracle& cad, Criteria& criteria) {
  std::vector<ThinFace> thin;
  const Box3 box = cad.bounding_box();
  const double h = std::min(criteria.facet_size(box.center()), criteria.cell_size(box.center()));
  for (const PatchInfo& p : cad.patches()) {
    const std::optional<double> t = cad.curved_thickness(p.id);
    if (!t) continue;
    const double size = std::max(kPerThickness * *t, kFloor * h);
    if (size < h) thin.push_back({cad.patch_box(p.id), size});
  }
  if (thin.empty()) return 0;
  auto limit = std::make_shared<const ThicknessLimit>(box, 0.25 * h, thin);
  auto limited = [limit](const ScalarField& f) {
    return ScalarField{0.0, [limit, f](const Point3& p) { return std::min(f(p), (*limit)(p)); }};
  };
  criteria.facet_size = limited(criteria.facet_size);
  criteria.cell_size = limited(criteria.cell_size);
  criteria.edge_size = limited(criteria.edge_size);
  return static_cast<int>(thin.size());
}

}  // namespace rdmesh::cli
