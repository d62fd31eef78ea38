// Sizes by curvature (rdmesh/curvature_sizes.h): curves and the first surface
// mesh's triangles sampled for their curvature, as graded pieces.
#include "rdmesh/curvature_sizes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "graded_field.h"

namespace rdmesh {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr int kMaxSplits = 5;         // levels of splitting a triangle in four
constexpr double kSplitRatio = 1.25;  // split while the sizes differ by more

/// Curvature sizes pi R / N from the oracle's answers, clamped and counted.
class Sizer {
 public:
  Sizer(double per_turn, double min_size, CurvatureStats& stats)
      : per_turn_(per_turn), min_size_(min_size), stats_(stats) {}

  /// The size for curvature k (nullopt: unknown): infinite where flat.
  double size(std::optional<double> k) {
    ++stats_.samples;
    if (!k) {
      ++stats_.unknown;
      return kInfinity;
    }
    if (!(*k > 0) || !std::isfinite(*k)) return kInfinity;
    const double radius = 1 / *k;
    if (stats_.min_radius == 0 || radius < stats_.min_radius) stats_.min_radius = radius;
    double h = M_PI * radius / per_turn_;
    if (h < min_size_) {
      ++stats_.clamped;
      h = min_size_;
    }
    return h;
  }

 private:
  double per_turn_, min_size_;
  CurvatureStats& stats_;
};

void add_curve(const DomainOracle& oracle, const CurveInfo& info, const Criteria& criteria,
               Sizer& sizer, detail::Pieces& pieces, std::vector<double>& sizes) {
  const Curve& c = oracle.curve(info.id);
  double t = info.t_begin;
  Point3 p = c.point(t);
  double h = sizer.size(c.curvature(t)), base = criteria.edge_size(p);
  for (int i = 0; i < 1000000 && t < info.t_end; ++i) {
    const double step = 0.5 * std::min(h, base);
    const double next = c.parameter_at_length(t, step);
    if (!(next > t)) break;
    const Point3 q = c.point(next);
    const double hq = sizer.size(c.curvature(next)), base_q = criteria.edge_size(q);
    const double size = std::min(h, hq);
    if (size < std::max(base, base_q)) {
      pieces.points.push_back(p);
      pieces.points.push_back(q);
      const int n = static_cast<int>(pieces.points.size());
      pieces.items.push_back({n - 2, n - 1, -1});
      sizes.push_back(size);
    }
    t = next, p = q, h = hq, base = base_q;
  }
}

/// Triangle (a, b, c) of a patch with the sizes at its corners: split in four
/// while its sizes vary, else one piece at its smallest size.
struct PatchSampler {
  const DomainOracle& oracle;
  const Criteria& criteria;
  PatchId patch;
  double slope, min_size, per_turn;
  Sizer& sizer;
  detail::Pieces& pieces;
  std::vector<double>& sizes;

  double at(const Point3& p) { return sizer.size(oracle.curvature(p, patch)); }

  void triangle(const Point3& a, const Point3& b, const Point3& c, double ha, double hb, double hc,
                int depth) {
    const Point3 g = (1.0 / 3) * (a + b + c);
    const double hg = at(g);
    const double lo = std::min({ha, hb, hc, hg}), hi = std::max({ha, hb, hc, hg});
    const double longest = std::max({distance(a, b), distance(b, c), distance(c, a)});
    if (lo == kInfinity) return;  // flat here
    if (depth < kMaxSplits && longest > 2 * lo && hi > kSplitRatio * lo) {
      const Point3 ab = 0.5 * (a + b), bc = 0.5 * (b + c), ca = 0.5 * (c + a);
      const double hab = at(ab), hbc = at(bc), hca = at(ca);
      triangle(a, ab, ca, ha, hab, hca, depth + 1);
      triangle(ab, b, bc, hab, hb, hbc, depth + 1);
      triangle(ca, bc, c, hca, hbc, hc, depth + 1);
      triangle(ab, bc, ca, hab, hbc, hca, depth + 1);
      return;
    }
    if (!(lo < criteria.facet_size(g))) return;
    pieces.points.insert(pieces.points.end(), {a, b, c});
    const int n = static_cast<int>(pieces.points.size());
    pieces.items.push_back({n - 3, n - 2, n - 1});
    // The piece is a chord of the first mesh, off the patch by its sag: at
    // most the facet distance, and longest^2 / (8 R) on a radius R >= the
    // one lo stands for. Lowered by what grading adds over that distance, the
    // size holds on the patch itself.
    const double radius = lo * per_turn / M_PI;
    const double sag = std::min(criteria.facet_distance(g), longest * longest / (8 * radius));
    // At most halved: a first mesh far coarser than the curvature (an explicit
    // large --size) has chords whose sag exceeds the size itself; there the
    // patch gets up to 2 x the size rather than the minimum size everywhere.
    sizes.push_back(std::max({min_size, lo - slope * sag, 0.5 * lo}));
  }
};

}  // namespace

CurvatureStats detail::add_curvature_pieces(const DomainOracle& oracle, const TetMesh& surface,
                                            const Criteria& criteria, double per_turn,
                                            GradedField& field) {
  CurvatureStats stats;
  stats.per_turn = per_turn;
  const double min_size = criteria.min_size_for(oracle.bounding_box());
  Sizer sizer(per_turn, min_size, stats);
  Pieces pieces;
  std::vector<double> sizes;
  for (const CurveInfo& info : oracle.curves())
    add_curve(oracle, info, criteria, sizer, pieces, sizes);
  // Patches: each vertex's size once per patch.
  std::unordered_map<long long, double> vertex_size;
  long long patches = 1;  // above every patch id
  for (const PatchInfo& info : oracle.patches())
    patches = std::max<long long>(patches, info.id.value + 1);
  std::vector<bool> sampled(static_cast<std::size_t>(patches), false);
  for (std::size_t f = 0; f < surface.triangles.size(); ++f) {
    const PatchId patch = surface.triangle_patch[f];
    if (patch.value <= 0 || patch.value >= patches) continue;
    sampled[static_cast<std::size_t>(patch.value)] = true;
    PatchSampler s{oracle,   criteria, patch,  field.slope(), min_size,
                   per_turn, sizer,    pieces, sizes};
    double h[3];
    for (int k = 0; k < 3; ++k) {
      const int v = surface.triangles[f][k];
      const auto [it, fresh] = vertex_size.try_emplace(v * patches + patch.value, 0.0);
      if (fresh) it->second = s.at(surface.vertices[v]);
      h[k] = it->second;
    }
    const auto& t = surface.triangles[f];
    s.triangle(surface.vertices[t[0]], surface.vertices[t[1]], surface.vertices[t[2]], h[0], h[1],
               h[2], 0);
  }
  // Patches the first mesh missed (too small for the base sizes): their initial points.
  for (const PatchInfo& info : oracle.patches()) {
    if (info.id.value < patches && sampled[static_cast<std::size_t>(info.id.value)]) continue;
    for (const Point3& p : oracle.initial_points(info.id)) {
      const double h = sizer.size(oracle.curvature(p, info.id));
      if (!(h < criteria.facet_size(p))) continue;
      pieces.points.push_back(p);
      const int n = static_cast<int>(pieces.points.size());
      pieces.items.push_back({n - 1, n - 1, -1});
      sizes.push_back(h);
    }
  }
  stats.pieces = pieces.items.size();
  if (!sizes.empty()) stats.min_size = *std::min_element(sizes.begin(), sizes.end());
  field.add_sized(pieces, sizes);
  return stats;
}

CurvatureAchieved achieved_curvature(const TetMesh& mesh, const DomainOracle& oracle,
                                     double per_turn, double min_size) {
  CurvatureAchieved a;
  auto target = [&](std::optional<double> k) {
    return k && *k > 0 && std::isfinite(*k) ? 2 * M_PI / (*k * per_turn) : kInfinity;
  };
  const std::vector<CurveInfo> curves = oracle.curves();
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
    const int id = mesh.edge_curve[e].value;
    if (id < 1 || id > static_cast<int>(curves.size())) continue;
    const Point3 &p = mesh.vertices[mesh.edges[e][0]], &q = mesh.vertices[mesh.edges[e][1]];
    const Curve& c = oracle.curve(curves[id - 1].id);
    const double t = c.closest(0.5 * (p + q), curves[id - 1].t_begin, curves[id - 1].t_end);
    const double goal = target(c.curvature(t));
    if (!(goal > 2 * min_size) || goal == kInfinity) continue;
    const double ratio = distance(p, q) / goal;
    ++a.curve_edges;
    if (ratio > 1) ++a.curve_over;
    a.curve_max_ratio = std::max(a.curve_max_ratio, ratio);
  }
  double sum = 0;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const auto& t = mesh.triangles[f];
    const Point3 &x = mesh.vertices[t[0]], &y = mesh.vertices[t[1]], &z = mesh.vertices[t[2]];
    const double goal = target(oracle.curvature((1.0 / 3) * (x + y + z), mesh.triangle_patch[f]));
    if (!(goal > 2 * min_size) || goal == kInfinity) continue;
    const double ratio = std::max({distance(x, y), distance(y, z), distance(z, x)}) / goal;
    ++a.facets;
    if (ratio > 1) ++a.facets_over;
    a.facet_max_ratio = std::max(a.facet_max_ratio, ratio);
    sum += ratio;
  }
  if (a.facets > 0) a.facet_mean_ratio = sum / static_cast<double>(a.facets);
  return a;
}

}  // namespace rdmesh
