#include "oracles/oracle_conformance.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <sstream>
#include <tuple>

namespace rdmesh {
namespace {

std::string str(const Point3& p) {
  std::ostringstream s;
  s.precision(17);
  s << "(" << p.x << ", " << p.y << ", " << p.z << ")";
  return s.str();
}

const PatchInfo* find_patch(const std::vector<PatchInfo>& patches, PatchId id) {
  for (const PatchInfo& p : patches) {
    if (p.id == id) return &p;
  }
  return nullptr;
}

/// True when {locate(p - d), locate(p + d)} are exactly the two sides of `patch`.
bool separates(const DomainOracle& o, const PatchInfo& patch, Point3 p, Point3 d) {
  const int l1 = o.locate(p - d).label.value, l2 = o.locate(p + d).label.value;
  return std::min(l1, l2) == patch.side_a.value && std::max(l1, l2) == patch.side_b.value;
}

/// p lies on the closure of the patch: both of its sides occur within |r| of p
/// (26 probes). Used where p may sit on the patch's boundary crease, where no
/// single direction need cross the patch itself.
bool touches(const DomainOracle& o, const PatchInfo& patch, Point3 p, double r) {
  bool seen_a = false, seen_b = false;
  for (int i = 0; i < 27; ++i) {
    const Point3 dir{double(i % 3 - 1), double(i / 3 % 3 - 1), double(i / 9 - 1)};
    if (i == 13) continue;
    const int l = o.locate(p + (r / norm(dir)) * dir).label.value;
    seen_a = seen_a || l == patch.side_a.value;
    seen_b = seen_b || l == patch.side_b.value;
  }
  return seen_a && seen_b;
}

void check_ids(const DomainOracle& o) {
  const std::vector<SubdomainInfo> subs = o.subdomains();
  for (std::size_t i = 0; i < subs.size(); ++i) {
    EXPECT_EQ(subs[i].id.value, static_cast<int>(i) + 1);
    EXPECT_FALSE(subs[i].name.empty());
  }
  const int n = static_cast<int>(subs.size());
  const std::vector<PatchInfo> patches = o.patches();
  EXPECT_FALSE(patches.empty());
  for (std::size_t i = 0; i < patches.size(); ++i) {
    const PatchInfo& p = patches[i];
    EXPECT_GE(p.id.value, 1);
    if (i > 0) {
      EXPECT_LT(patches[i - 1].id, p.id) << "patch ids must ascend";
    }
    EXPECT_GE(p.side_a.value, 0);
    EXPECT_LT(p.side_a, p.side_b) << "patch " << p.id.value;
    EXPECT_LE(p.side_b.value, n) << "patch " << p.id.value;
    EXPECT_FALSE(p.name.empty());
  }
}

void check_outside_box(const DomainOracle& o, std::mt19937& rng, int samples) {
  const Box3 box = o.bounding_box();
  const Point3 size = box.hi - box.lo;
  std::uniform_real_distribution<double> u(-1.0, 2.0);
  const int n = static_cast<int>(o.subdomains().size());
  for (int i = 0; i < samples; ++i) {
    const Point3 p{box.lo.x + u(rng) * size.x, box.lo.y + u(rng) * size.y,
                   box.lo.z + u(rng) * size.z};
    const int label = o.locate(p).label.value;
    if (!box.contains(p)) {
      EXPECT_EQ(label, 0) << "locate" << str(p) << " outside the box";
    } else {
      EXPECT_GE(label, 0);
      EXPECT_LE(label, n);
    }
  }
}

/// `hit` meets intersect()'s guarantee for [a, b]: on the segment, on a listed
/// patch whose two sides are the labels just before and after it.
void expect_valid_hit(const DomainOracle& o, const std::vector<PatchInfo>& patches, const Point3& a,
                      const Point3& b, const SurfaceHit& hit, const char* what) {
  const double tol = o.tolerance(), length = distance(a, b);
  const Point3 dir = (1 / length) * (b - a);
  const double t = dot(hit.point - a, dir);
  EXPECT_LE(distance(hit.point, a + t * dir), tol) << what << " is off the segment";
  EXPECT_GE(t, -tol) << what;
  EXPECT_LE(t, length + tol) << what;
  const PatchInfo* patch = find_patch(patches, hit.patch);
  EXPECT_NE(patch, nullptr) << what << ": patch " << hit.patch.value << " is not listed";
  if (patch) {
    EXPECT_TRUE(separates(o, *patch, hit.point, 4 * tol * dir))
        << "labels across " << what << " " << str(hit.point) << " on " << str(a) << " - " << str(b)
        << " are not the sides of patch " << patch->name;
  }
}

void check_segments(const DomainOracle& o, std::mt19937& rng, int samples) {
  const Box3 box = o.bounding_box();
  const double diag = box.diagonal(), tol = o.tolerance();
  const std::vector<PatchInfo> patches = o.patches();
  std::uniform_real_distribution<double> u(0.0, 1.0);
  auto in_box = [&] {
    return Point3{box.lo.x + u(rng) * (box.hi.x - box.lo.x),
                  box.lo.y + u(rng) * (box.hi.y - box.lo.y),
                  box.lo.z + u(rng) * (box.hi.z - box.lo.z)};
  };
  int crossing = 0;
  for (int i = 0; i < samples; ++i) {
    const Point3 a = in_box();
    Point3 b = in_box();
    if (i % 2) {  // short segment: random direction, length 1e-3..1 of the diagonal
      const double len = diag * std::pow(10.0, -3.0 * u(rng));
      b = a + (len / std::max(norm(b - a), 1e-300)) * (b - a);
      if (!box.contains(b)) continue;
    }
    if (!(distance(a, b) > 100 * tol)) continue;
    const Located at_a = o.locate(a), at_b = o.locate(b);
    const SubdomainId la = at_a.label, lb = at_b.label;
    const bool differ = la != lb;
    EXPECT_FALSE(at_a.crossing || at_b.crossing) << "a crossing without a hint";
    // With a hint (the refiner's walk from a labeled neighbor): the same label,
    // and any crossing returned is a valid hit of the segment to the hint.
    for (const auto& [p, q, lp, lq] : {std::tuple{a, b, la, lb}, std::tuple{b, a, lb, la}}) {
      const Located walked = o.locate(p, LocateHint{q, lq});
      EXPECT_EQ(walked.label, lp) << "locate from a hint on " << str(p) << " - " << str(q);
      if (walked.crossing) expect_valid_hit(o, patches, p, q, *walked.crossing, "the crossing");
      const Located again = o.locate(p, LocateHint{q, lq});
      EXPECT_TRUE(again.label == walked.label &&
                  again.crossing.has_value() == walked.crossing.has_value() &&
                  (!again.crossing || (again.crossing->point == walked.crossing->point &&
                                       again.crossing->patch == walked.crossing->patch)))
          << "locate with a hint is not deterministic";
    }
    const std::optional<SurfaceHit> hit = o.intersect(a, b);
    crossing += differ;
    if (differ) {
      EXPECT_TRUE(hit.has_value()) << "no hit on " << str(a) << " - " << str(b);
    }
    if (!hit) continue;
    expect_valid_hit(o, patches, a, b, *hit, "the hit");
    const std::optional<SurfaceHit> again = o.intersect(a, b);
    EXPECT_TRUE(again && again->point == hit->point && again->patch == hit->patch)
        << "intersect is not deterministic";
  }
  EXPECT_GT(crossing, 0) << "no random segment crossed a patch";
}

/// A unit normal of `patch` at x (on it), from the projection of nearby points.
std::optional<Point3> normal_at(const DomainOracle& o, PatchId patch, Point3 x) {
  const double delta = 1e-4 * o.bounding_box().diagonal();
  std::optional<Point3> best;
  double best_len = 0;
  for (Point3 v : {Point3{1, 0, 0}, Point3{0, 1, 0}, Point3{0, 0, 1}}) {
    const Point3 p = x + delta * v;
    const std::optional<Point3> q = o.project(p, patch);
    if (q && distance(p, *q) > best_len) {
      best_len = distance(p, *q);
      best = (1 / best_len) * (p - *q);
    }
  }
  if (best_len < 0.3 * delta) return std::nullopt;
  return best;
}

void check_initial_points_and_projection(const DomainOracle& o, std::mt19937& rng) {
  const double tol = o.tolerance(), diag = o.bounding_box().diagonal();
  std::normal_distribution<double> gauss;
  for (const PatchInfo& patch : o.patches()) {
    const std::vector<Point3> points = o.initial_points(patch.id);
    EXPECT_GE(points.size(), 3u) << "patch " << patch.name;
    std::set<std::tuple<double, double, double>> distinct;
    for (const Point3& x : points) {
      distinct.insert({x.x, x.y, x.z});
      EXPECT_TRUE(o.bounding_box().contains(x));
      const std::optional<Point3> back = o.project(x, patch.id);
      EXPECT_TRUE(back && distance(*back, x) <= 10 * tol)
          << "initial point " << str(x) << " of patch " << patch.name << " is not on it";
      const std::optional<Point3> n = normal_at(o, patch.id, x);
      EXPECT_TRUE(n.has_value()) << "no normal at " << str(x);
      if (n) {
        EXPECT_TRUE(separates(o, patch, x, 8 * tol * *n))
            << "labels across initial point " << str(x) << " are not the sides of " << patch.name;
      }
      // Projection of a perturbed point: on the patch, near x, not farther than x.
      const double eps = 1e-3 * diag;
      Point3 v{gauss(rng), gauss(rng), gauss(rng)};
      v = (eps / norm(v)) * v;
      const Point3 p = x + v;
      const std::optional<Point3> q = o.project(p, patch.id);
      EXPECT_TRUE(q.has_value()) << "project" << str(p) << " failed on " << patch.name;
      if (!q) continue;
      EXPECT_LE(distance(*q, x), 2 * eps + 10 * tol);
      EXPECT_LE(distance(*q, p), eps + 10 * tol) << "projection farther than a known point";
      if (distance(*q, p) > 0.01 * eps) {
        const Point3 d = (1 / distance(*q, p)) * (p - *q);
        EXPECT_TRUE(separates(o, patch, *q, 8 * tol * d) || touches(o, patch, *q, 8 * tol))
            << "projection " << str(*q) << " of " << str(p) << " is not on " << patch.name;
      }
    }
    EXPECT_EQ(distinct.size(), points.size()) << "duplicate initial points on " << patch.name;
  }
}

}  // namespace

void expect_oracle_conformance(const DomainOracle& oracle, int samples, unsigned seed,
                               bool with_features) {
  std::mt19937 rng(seed);
  const Box3 box = oracle.bounding_box();
  const double diag = box.diagonal();
  ASSERT_TRUE(std::isfinite(diag));
  ASSERT_TRUE(box.lo.x < box.hi.x && box.lo.y < box.hi.y && box.lo.z < box.hi.z);
  EXPECT_GT(oracle.tolerance(), 0.0);
  EXPECT_LT(oracle.tolerance(), 1e-3 * diag);
  check_ids(oracle);
  check_outside_box(oracle, rng, samples);
  check_segments(oracle, rng, samples);
  check_initial_points_and_projection(oracle, rng);
  if (with_features) expect_feature_conformance(oracle, seed);
}

}  // namespace rdmesh
