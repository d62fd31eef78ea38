#include "tet_quality.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rdmesh::view::detail {
namespace {

constexpr double kDegree = std::numbers::pi / 180;

/// The cosines of the six dihedral angles of a tetrahedron, from its face
/// normals: the angle at the edge shared by faces i and j is pi minus the
/// angle between their outward normals. A face of zero area gives cosine 1
/// (angle 0) at its edges; so do overflowing coordinates.
std::array<double, 6> dihedral_cosines(const Point3 (&p)[4]) {
  Point3 n[4];
  double length[4];
  for (int k = 0; k < 4; ++k) {
    const Point3& a = p[(k + 1) % 4];
    n[k] = cross(p[(k + 2) % 4] - a, p[(k + 3) % 4] - a);
    if (dot(n[k], p[k] - a) > 0) n[k] = -1.0 * n[k];  // away from the opposite vertex
    length[k] = norm(n[k]);
  }
  std::array<double, 6> cosines{};
  int e = 0;
  for (int i = 0; i < 4; ++i) {
    for (int j = i + 1; j < 4; ++j, ++e) {
      const double c = -dot(n[i], n[j]) / (length[i] * length[j]);
      cosines[e] = c >= -1 && c <= 1 ? c : c < -1 ? -1 : 1;  // NaN (zero area) -> 1
    }
  }
  return cosines;
}

/// Bin bounds: cos(5 m degrees), m = 1..35, decreasing.
std::array<double, kHistogramBins - 1> bin_bounds() {
  std::array<double, kHistogramBins - 1> b{};
  for (int m = 1; m < kHistogramBins; ++m) b[m - 1] = std::cos(5 * m * kDegree);
  return b;
}

}  // namespace

TetQuality measure_tets(const ViewMesh& mesh, double threshold) {
  static const std::array<double, kHistogramBins - 1> bounds = bin_bounds();
  TetQuality q;
  q.min_angle.resize(mesh.tets.size());
  double largest_cosine = -1, smallest_cosine = 1;
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    const auto& tet = mesh.tets[t];
    const Point3 p[4] = {mesh.points[tet[0]], mesh.points[tet[1]], mesh.points[tet[2]],
                         mesh.points[tet[3]]};
    double worst = -1;
    for (double c : dihedral_cosines(p)) {
      worst = std::max(worst, c);
      smallest_cosine = std::min(smallest_cosine, c);
      // The angle is at least 5 m degrees exactly when c <= cos(5 m degrees).
      const auto bin =
          std::partition_point(bounds.begin(), bounds.end(), [c](double b) { return b >= c; });
      ++q.histogram[static_cast<std::size_t>(bin - bounds.begin())];
    }
    largest_cosine = std::max(largest_cosine, worst);
    q.min_angle[t] = static_cast<float>(std::acos(worst) / kDegree);
    if (q.min_angle[t] < threshold) ++q.below;
  }
  if (!mesh.tets.empty()) {
    q.min = std::acos(largest_cosine) / kDegree;
    q.max = std::acos(smallest_cosine) / kDegree;
  }
  return q;
}

}  // namespace rdmesh::view::detail
