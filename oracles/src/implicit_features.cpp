// ImplicitOracle::build_features: the curves L and corners Q of an implicit
// domain from the declared curves (see rdmesh/implicit_oracle.h).
//
// 1. Validate each declared curve: a curve, a finite range, inside the box.
// 2. Find meeting points of every pair of curves: close pairs of chords of
//    sampled polylines, refined by alternating closest-point queries.
// 3. Split each curve at the meeting points interior to it (a closed curve
//    split at k >= 1 points gives k pieces, one wrapping around its seam).
// 4. Corners: endpoints of the open pieces, merged; pieces snap to them.
// 5. Patches: labels probed on small circles around each piece.

#include <algorithm>
#include <cmath>
#include <sstream>

#include "curve_piece.h"
#include "rdmesh/errors.h"
#include "rdmesh/implicit_oracle.h"

namespace rdmesh {

namespace {

constexpr int kSamples = 256;    // chords per curve for meeting detection
constexpr double kMerge = 1e-7;  // corner merge distance / box diagonal
constexpr double kProbe = 1e-5;  // probe circle radius / box diagonal
constexpr int kProbeDirections = 32;
constexpr int kProbeStations = 8;

std::string str(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

std::string str(const Point3& p) {
  return "(" + str(p.x) + ", " + str(p.y) + ", " + str(p.z) + ")";
}

/// A declared curve after validation.
struct Declared {
  std::string name;
  std::shared_ptr<const Curve> curve;
  double t0, t1;
  bool closed;
  std::vector<double> params;  // kSamples + 1 uniform parameters
  std::vector<Point3> points;
  std::vector<double> splits;
};

/// Closest points of segments [p0, p1] and [q0, q1]: fractions (s, t) and distance.
struct SegmentPair {
  double s, t, dist;
};

SegmentPair closest_on_segments(Point3 p0, Point3 p1, Point3 q0, Point3 q1) {
  const Point3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
  double s = 0, t = 0;
  if (a <= 0 && e <= 0) {
  } else if (a <= 0) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = dot(d1, r);
    if (e <= 0) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = dot(d1, d2), denom = a * e - b * b;
      s = denom > 0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0) {
        t = 0, s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1) {
        t = 1, s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  return {s, t, distance(p0 + s * d1, q0 + t * d2)};
}

/// Meeting points of curves u and v, refined from close chord pairs; adds the
/// interior ones to the curves' split lists.
void find_meetings(Declared& u, Declared& v, double merge) {
  std::vector<Point3> found;
  for (int i = 0; i < kSamples; ++i) {
    const double li = distance(u.points[i], u.points[i + 1]);
    for (int j = 0; j < kSamples; ++j) {
      const double lj = distance(v.points[j], v.points[j + 1]);
      const SegmentPair c =
          closest_on_segments(u.points[i], u.points[i + 1], v.points[j], v.points[j + 1]);
      const double reach = std::max(li, lj) + merge;
      if (c.dist > reach) continue;
      const Point3 approx = u.points[i] + c.s * (u.points[i + 1] - u.points[i]);
      if (std::any_of(found.begin(), found.end(),
                      [&](const Point3& f) { return distance(f, approx) <= 2 * reach; })) {
        continue;
      }
      // Alternating closest points within windows of three chords.
      const double ua = u.params[std::max(i - 1, 0)], ub = u.params[std::min(i + 2, kSamples)];
      const double va = v.params[std::max(j - 1, 0)], vb = v.params[std::min(j + 2, kSamples)];
      double su = u.params[i] + c.s * (u.params[i + 1] - u.params[i]);
      double sv = v.params[j] + c.t * (v.params[j + 1] - v.params[j]);
      double dist = distance(u.curve->point(su), v.curve->point(sv));
      for (int it = 0; it < 200 && dist > 0; ++it) {
        sv = v.curve->closest(u.curve->point(su), va, vb);
        su = u.curve->closest(v.curve->point(sv), ua, ub);
        const double next = distance(u.curve->point(su), v.curve->point(sv));
        if (!(next < dist * (1 - 1e-6))) {
          dist = std::min(dist, next);
          break;
        }
        dist = next;
      }
      if (dist > merge) continue;
      const Point3 meet = u.curve->point(su);
      found.push_back(meet);
      for (auto [d, s] : {std::pair<Declared*, double>{&u, su}, {&v, sv}}) {
        const bool at_end = !d->closed && (distance(meet, d->points.front()) <= merge ||
                                           distance(meet, d->points.back()) <= merge);
        if (!at_end) d->splits.push_back(s);
      }
    }
  }
}

}  // namespace

std::vector<PatchId> ImplicitOracle::patches_around(const Curve& curve, double t_begin,
                                                    double t_end, const std::string& name) const {
  const double diag = box_.diagonal(), radius = kProbe * diag;
  std::vector<PatchId> out;
  for (int k = 0; k < kProbeStations; ++k) {
    const double t = t_begin + (t_end - t_begin) * (k + 0.5) / kProbeStations;
    const double dt = 1e-6 * (t_end - t_begin);
    const Point3 x = curve.point(t);
    Point3 tangent = curve.point(t + dt) - curve.point(t - dt);
    const double tn = norm(tangent);
    if (!(tn > 0)) continue;  // a stationary point: no normal plane
    tangent = (1 / tn) * tangent;
    const Point3 axis = std::fabs(tangent.x) < 0.6   ? Point3{1, 0, 0}
                        : std::fabs(tangent.y) < 0.6 ? Point3{0, 1, 0}
                                                     : Point3{0, 0, 1};
    Point3 u = cross(tangent, axis);
    u = (1 / norm(u)) * u;
    const Point3 w = cross(tangent, u);
    int labels[kProbeDirections];
    Point3 probes[kProbeDirections];
    bool several = false;
    for (int d = 0; d < kProbeDirections; ++d) {
      const double angle = 2 * 3.141592653589793 * d / kProbeDirections;
      probes[d] = x + (radius * std::cos(angle)) * u + (radius * std::sin(angle)) * w;
      labels[d] = locate(probes[d]).label.value;
      several = several || labels[d] != labels[0];
    }
    if (!several) {
      throw InputError("curve '" + name + "' is not on the boundary of the domain: around " +
                       str(x) + " (t = " + str(t) + ") every point has label " +
                       std::to_string(labels[0]));
    }
    for (int d = 0; d < kProbeDirections; ++d) {
      const int a = labels[d], b = labels[(d + 1) % kProbeDirections];
      if (a == b) continue;
      // The patch crossed between two adjacent probes (several functions may
      // separate the same two labels around a curve: a cylinder's side and cap).
      const auto hit = intersect(probes[d], probes[(d + 1) % kProbeDirections]);
      if (hit) out.push_back(hit->patch);
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

void ImplicitOracle::build_features(std::vector<CurveSpec> specs) {
  const double merge = kMerge * box_.diagonal();
  std::vector<Declared> curves;
  for (std::size_t i = 0; i < specs.size(); ++i) {
    CurveSpec& spec = specs[i];
    Declared d{spec.name.empty() ? "curve_" + std::to_string(i + 1) : spec.name,
               std::move(spec.curve),
               spec.t_begin,
               spec.t_end,
               false,
               {},
               {},
               {}};
    const std::string prefix = "curve '" + d.name + "': ";
    if (!d.curve) throw InputError(prefix + "no curve given");
    if (!std::isfinite(d.t0) || !std::isfinite(d.t1) || !(d.t0 < d.t1)) {
      throw InputError(prefix + "bad parameter range [" + str(d.t0) + ", " + str(d.t1) +
                       "] (need finite t_begin < t_end)");
    }
    for (int k = 0; k <= kSamples; ++k) {
      const double t = k == kSamples ? d.t1 : d.t0 + (d.t1 - d.t0) * k / kSamples;
      const Point3 p = d.curve->point(t);
      if (!box_.contains(p)) {
        throw InputError(prefix + "leaves the bounding box at t = " + str(t) + ", point " + str(p));
      }
      d.params.push_back(t);
      d.points.push_back(p);
    }
    // A curve of no length (constant coordinates) is a point: the planner of
    // protecting balls would find nothing to cover and fail as on a broken oracle.
    const double length = d.curve->length(d.t0, d.t1);
    if (!(length > tolerance_)) {
      throw InputError(prefix + "it is a point, not a curve: its length " + str(length) +
                       " is not above the tolerance " + str(tolerance_));
    }
    d.closed = distance(d.points.front(), d.points.back()) <= merge;
    curves.push_back(std::move(d));
  }
  for (std::size_t i = 0; i < curves.size(); ++i) {
    for (std::size_t j = i + 1; j < curves.size(); ++j) find_meetings(curves[i], curves[j], merge);
  }

  // Corners of open pieces, merged, ids in order of first appearance.
  auto corner_at = [&](const Point3& p) {
    for (const CornerInfo& c : features_.corners()) {
      if (distance(c.point, p) <= merge) return c;
    }
    return features_.add_corner(p);
  };
  for (Declared& d : curves) {
    // Sorted split parameters, distinct points, none at a closed curve's seam twice.
    std::vector<double>& s = d.splits;
    std::sort(s.begin(), s.end());
    std::vector<double> cuts;
    for (double t : s) {
      const Point3 p = d.curve->point(t);
      if (!cuts.empty() && distance(p, d.curve->point(cuts.back())) <= merge) continue;
      if (d.closed && !cuts.empty() && distance(p, d.curve->point(cuts.front())) <= merge) continue;
      cuts.push_back(t);
    }
    std::vector<std::pair<double, double>> ranges;
    if (!d.closed) {
      double from = d.t0;
      for (double t : cuts) ranges.push_back({from, t}), from = t;
      ranges.push_back({from, d.t1});
    } else if (!cuts.empty()) {
      for (std::size_t k = 0; k + 1 < cuts.size(); ++k) ranges.push_back({cuts[k], cuts[k + 1]});
      ranges.push_back({cuts.back(), cuts.front() + (d.t1 - d.t0)});
    }
    const bool closed_piece = d.closed && cuts.empty();
    if (closed_piece) ranges.push_back({d.t0, d.t1});
    for (std::size_t k = 0; k < ranges.size(); ++k) {
      const auto [a, b] = ranges[k];
      const CurveId id = features_.next_curve_id();
      CurveInfo info{id,
                     ranges.size() == 1 ? d.name : d.name + "#" + std::to_string(k + 1),
                     closed_piece,
                     a,
                     b,
                     CornerId(0),
                     CornerId(0),
                     {}};
      const double period = d.t1 - d.t0;
      auto at = [&](double t) { return d.curve->point(t > d.t1 ? t - period : t); };
      Point3 start = at(a), end = closed_piece ? start : at(b);
      if (!closed_piece) {
        const CornerInfo cs = corner_at(start);
        const CornerInfo ce = corner_at(end);
        info.start = cs.id, info.end = ce.id, start = cs.point, end = ce.point;
      }
      auto piece = std::make_unique<detail::CurvePiece>(d.curve, d.t0, d.t1, a, b, start, end);
      info.patches = patches_around(*piece, a, b, info.name);
      features_.add_curve(std::move(info), std::move(piece));
    }
  }
  for (const CurveInfo& c : features_.curves()) {
    if (c.closed) continue;
    for (CornerId corner : {c.start, c.end}) {
      CornerInfo& q = features_.corner(corner);
      if (q.curves.empty() || q.curves.back() != c.id) q.curves.push_back(c.id);
      q.patches.insert(q.patches.end(), c.patches.begin(), c.patches.end());
    }
  }
  for (CornerInfo& q : features_.corners()) {
    std::sort(q.patches.begin(), q.patches.end());
    q.patches.erase(std::unique(q.patches.begin(), q.patches.end()), q.patches.end());
  }
}

}  // namespace rdmesh
