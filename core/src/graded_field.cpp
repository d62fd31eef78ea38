// Graded sizes around pieces of the domain (graded_field.h).
#include "graded_field.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "rdmesh/mesher.h"

namespace rdmesh::detail {
namespace {

Point3 closest_on_segment(const Point3& x, const Point3& a, const Point3& b) {
  const Point3 d = b - a;
  const double len2 = squared_norm(d);
  const double t = len2 > 0 ? std::clamp(dot(x - a, d) / len2, 0.0, 1.0) : 0.0;
  return a + t * d;
}

std::vector<Box3> boxes(const Pieces& pieces) {
  std::vector<Box3> out;
  out.reserve(pieces.items.size());
  for (const auto& it : pieces.items) {
    Box3 b{pieces.points[it[0]], pieces.points[it[0]]};
    for (int k = 1; k < 3 && it[k] >= 0; ++k) {
      const Point3& q = pieces.points[it[k]];
      b.lo = {std::min(b.lo.x, q.x), std::min(b.lo.y, q.y), std::min(b.lo.z, q.z)};
      b.hi = {std::max(b.hi.x, q.x), std::max(b.hi.y, q.y), std::max(b.hi.z, q.z)};
    }
    out.push_back(b);
  }
  return out;
}

}  // namespace

GradedSize::GradedSize(Pieces pieces, double size, double slope)
    : pieces_(std::move(pieces)), bvh_(boxes(pieces_)), size_(size), slope_(slope) {}

double GradedSize::below(const Point3& p, double bound) const {
  if (bound <= size_) return bound;
  const double reach = (bound - size_) / slope_;
  double best = reach * reach;
  bvh_.nearest([&](const Box3& b) { return squared_distance(b, p); },
               [&](int i, double& best_so_far) {
                 const auto& it = pieces_.items[i];
                 const Point3& a = pieces_.points[it[0]];
                 const Point3& b = pieces_.points[it[1]];
                 const Point3 q = it[2] < 0 ? closest_on_segment(p, a, b)
                                            : closest_on_triangle(p, a, b, pieces_.points[it[2]]);
                 best_so_far = std::min(best_so_far, squared_norm(q - p));
               },
               best);
  return std::min(bound, size_ + slope_ * std::sqrt(best));
}

void GradedField::add(Pieces pieces, double size) {
  if (pieces.items.empty()) return;
  auto set = std::make_unique<GradedSize>(std::move(pieces), size, slope_);
  const auto at = std::upper_bound(sets_.begin(), sets_.end(), size,
                                   [](double s, const auto& g) { return s < g->size(); });
  sets_.insert(at, std::move(set));
}

void GradedField::add_sized(const Pieces& pieces, const std::vector<double>& sizes) {
  std::map<long, std::pair<Pieces, double>> classes;  // floor(log_1.1 size) -> pieces, min size
  for (std::size_t i = 0; i < pieces.items.size(); ++i) {
    const long key = static_cast<long>(std::floor(std::log(sizes[i]) / std::log(1.1)));
    auto [it, fresh] = classes.try_emplace(key, Pieces{}, sizes[i]);
    auto& [out, size] = it->second;
    size = std::min(size, sizes[i]);
    std::array<int, 3> item{-1, -1, -1};
    for (int k = 0; k < 3 && pieces.items[i][k] >= 0; ++k) {
      out.points.push_back(pieces.points[pieces.items[i][k]]);
      item[k] = static_cast<int>(out.points.size()) - 1;
    }
    out.items.push_back(item);
  }
  for (auto& [key, set] : classes) add(std::move(set.first), set.second);
}

double GradedField::below(const Point3& p, double bound) const {
  for (const auto& g : sets_) {
    if (bound <= g->size()) break;  // sorted: no later set can lower it
    bound = g->below(p, bound);
  }
  return bound;
}

ScalarField lowered(const ScalarField& base, std::shared_ptr<const GradedField> near,
                    std::shared_ptr<const std::vector<std::pair<int, double>>> inside,
                    const DomainOracle* oracle) {
  // Read-only data and the oracle's queries (thread-safe where the refinement
  // calls it from several threads: MeshOptions::oracle_concurrent).
  return ScalarField::composed(
      [base, near, inside, oracle](const Point3& p) {
        double h = near->below(p, base(p));
        if (inside && !inside->empty()) {
          const int label = oracle->locate(p).label.value;
          for (const auto& [id, size] : *inside) {
            if (id == label) h = std::min(h, size);
          }
        }
        return h;
      },
      {&base});
}

TetMesh sampling_surface(const DomainOracle& oracle, const Criteria& criteria) {
  MeshOptions first;
  first.surface_only = true;
  first.exudation.enabled = false;
  return generate_mesh(oracle, criteria, first).mesh;
}

}  // namespace rdmesh::detail
