#include "domain_file_limits.h"

#include <algorithm>
#include <cmath>

#include "rdmesh/curve.h"
#include "rdmesh/errors.h"
#include "rdmesh/number_text.h"

namespace rdmesh::detail {

void check_json_depth(const std::string& text) {
  int depth = 0;
  const std::size_t n = text.size();
  for (std::size_t i = 0; i < n; ++i) {
    const char c = text[i];
    if (c == '"') {  // skip the string, escapes included
      for (++i; i < n && text[i] != '"'; ++i) {
        if (text[i] == '\\') ++i;
      }
    } else if (c == '/' && i + 1 < n && text[i + 1] == '/') {
      while (i < n && text[i] != '\n') ++i;
    } else if (c == '/' && i + 1 < n && text[i + 1] == '*') {
      const std::size_t end = text.find("*/", i + 2);
      i = end == std::string::npos ? n : end + 1;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth) {
        throw InputError("arrays and objects nested deeper than " + std::to_string(kMaxJsonDepth) +
                         " levels (at byte " + std::to_string(i) + ")");
      }
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
}

void check_expression_length(const std::string& text, const std::string& what) {
  if (text.size() > kMaxExpressionLength) {
    throw InputError(what + " is " + std::to_string(text.size()) + " characters long, at most " +
                     std::to_string(kMaxExpressionLength));
  }
}

void check_box_size(const Box3& box) {
  const Point3 e = box.hi - box.lo;
  const double largest = std::max({e.x, e.y, e.z});
  const double magnitude = std::max({std::abs(box.lo.x), std::abs(box.lo.y), std::abs(box.lo.z),
                                     std::abs(box.hi.x), std::abs(box.hi.y), std::abs(box.hi.z)});
  const char* axis = "xyz";
  const double extent[3] = {e.x, e.y, e.z};
  for (int k = 0; k < 3; ++k) {
    const std::string what =
        std::string("'bbox' extent along ") + axis[k] + " " + short_number(extent[k]);
    if (!std::isfinite(extent[k]) || extent[k] > 1e12) throw InputError(what + " is above 1e12");
    if (extent[k] < 1e-6) {
      throw InputError(what + " is below 1e-6: scale the functions to larger units");
    }
    if (extent[k] < 1e-6 * largest) {
      throw InputError(what + " is below 1e-6 of the largest extent " + short_number(largest) +
                       ": the box is flat");
    }
    if (extent[k] < 1e-6 * magnitude) {
      throw InputError(what + " is below 1e-6 of its coordinates' magnitude " +
                       short_number(magnitude) +
                       ": double precision cannot resolve it (move the box near the origin)");
    }
  }
}

void check_domain_inside_box(const DomainOracle& oracle) {
  const Box3 box = oracle.bounding_box();
  constexpr int n = 32;  // intervals per face side
  const double lo[3] = {box.lo.x, box.lo.y, box.lo.z}, hi[3] = {box.hi.x, box.hi.y, box.hi.z};
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (int side = 0; side < 2; ++side) {
      for (int i = 0; i <= n; ++i) {
        for (int j = 0; j <= n; ++j) {
          double c[3];
          c[axis] = side ? hi[axis] : lo[axis];
          c[u] = i == n ? hi[u] : lo[u] + (hi[u] - lo[u]) * i / n;
          c[v] = j == n ? hi[v] : lo[v] + (hi[v] - lo[v]) * j / n;
          const Point3 p{c[0], c[1], c[2]};
          const SubdomainId s = oracle.locate(p).label;
          if (s == kOutside) continue;
          std::string name = std::to_string(s.value);
          for (const SubdomainInfo& info : oracle.subdomains()) {
            if (info.id == s) name = "'" + info.name + "'";
          }
          throw InputError("the domain reaches the bounding box: " + point_text(p) +
                           ", on the box, is inside subdomain " + name +
                           " (the box must contain the whole domain; check the functions' "
                           "signs, negative inside)");
        }
      }
    }
  }
}

void check_curve_length(const std::function<Point3(double)>& gamma, double t0, double t1,
                        double diagonal) {
  // Jittered parameters (golden-ratio offsets in each of kChords equal steps): a
  // uniform sample aliases a periodic curve (10^6 turns look like 0.14 turn a step).
  constexpr int kChords = 4096;
  std::vector<Point3> points;
  for (int i = 0; i <= kChords; ++i) {
    const double jitter = i == 0 || i == kChords ? 0 : std::fmod(i * 0.6180339887498949, 1.0);
    const Point3 p = gamma(i == kChords ? t1 : t0 + (t1 - t0) * (i + jitter) / kChords);
    if (!is_finite(p)) return;  // the curve's own reader names the point
    points.push_back(p);
  }
  // A curve whose points all coincide (constant expressions, a 't' range
  // below the resolution of double) is a point: the planner of protecting balls
  // would find it no length to cover.
  double spread = 0;
  for (const Point3& p : points) spread = std::max(spread, distance(p, points.front()));
  if (!(spread > kMinCurveExtentInDiagonals * diagonal)) {
    throw InputError("it is a point, not a curve: its " + std::to_string(kChords + 1) +
                     " sampled points all lie within " + short_number(spread) + " of " +
                     point_text(points.front()) + " (check the expressions and the 't' range)");
  }
  // An inscribed polygon is no longer and turns no more than its curve (Milnor).
  double length = 0, turning = 0;
  for (int i = 1; i <= kChords; ++i) {
    length += distance(points[i - 1], points[i]);
    if (i == kChords) break;
    const Point3 c1 = points[i] - points[i - 1], c2 = points[i + 1] - points[i];
    if (squared_norm(c1) > 0 && squared_norm(c2) > 0) {
      turning += std::atan2(norm(cross(c1, c2)), dot(c1, c2));
    }
  }
  if (!(length <= kMaxCurveLengthInDiagonals * diagonal)) {
    throw InputError("it is at least " + short_number(length) + " long (" +
                     std::to_string(kChords) + " chords), more than " +
                     short_number(kMaxCurveLengthInDiagonals) +
                     " box diagonals (check the 't' range)");
  }
  const double turns = turning / (2 * 3.141592653589793);
  if (turns > kMaxCurveTurns) {
    throw InputError("it turns at least " + short_number(turns) + " times (" +
                     std::to_string(kChords) + " chords), more than " +
                     short_number(kMaxCurveTurns) + " (check the 't' range)");
  }
}

void check_no_self_overlap(const Curve& curve, double t0, double t1, double diagonal) {
  constexpr int kPoints = 64, kOverlapping = 4;
  const double length = curve.length(t0, t1), step = length / kPoints;
  if (!(length > 0)) return;
  int overlapping = 0;
  Point3 first;
  for (int i = 0; i < kPoints; ++i) {
    const double s = (i + 0.5) * step;
    const double t = curve.parameter_at_length(t0, s);
    const Point3 p = curve.point(t);
    const double before = curve.parameter_at_length(t0, std::max(0.0, s - step));
    const double after = curve.parameter_at_length(t0, std::min(length, s + step));
    double nearest = INFINITY;
    if (before > t0) nearest = distance(p, curve.point(curve.closest(p, t0, before)));
    if (after < t1)
      nearest = std::min(nearest, distance(p, curve.point(curve.closest(p, after, t1))));
    if (nearest <= 1e-7 * diagonal && overlapping++ == 0) first = p;
  }
  if (overlapping >= kOverlapping) {
    throw InputError("it runs over itself (" + std::to_string(overlapping) + " of " +
                     std::to_string(kPoints) +
                     " points at equal arc length lie on another part "
                     "of it, e.g. " +
                     point_text(first) + "): give each part once (check the 't' range)");
  }
}

void check_distinct_curves(const std::vector<std::pair<std::string, const Curve*>>& curves,
                           const std::vector<std::pair<double, double>>& ranges, double diagonal) {
  std::vector<double> lengths;
  for (std::size_t a = 0; a < curves.size(); ++a) {
    lengths.push_back(curves[a].second->length(ranges[a].first, ranges[a].second));
  }
  for (std::size_t a = 0; a < curves.size(); ++a) {
    for (std::size_t b = 0; b < a; ++b) {
      if (!(std::abs(lengths[a] - lengths[b]) <= 1e-9 * std::max(lengths[a], lengths[b]))) {
        continue;
      }
      const Curve& ca = *curves[a].second;
      const Curve& cb = *curves[b].second;
      const auto [a0, a1] = ranges[a];
      const auto [b0, b1] = ranges[b];
      bool same = true;
      for (int k = 1; k < 8 && same; ++k) {
        const Point3 p = ca.point(a0 + (a1 - a0) * k / 8);
        same = distance(p, cb.point(cb.closest(p, b0, b1))) <= 1e-7 * diagonal;
      }
      if (same) {
        throw InputError("curves '" + curves[b].first + "' and '" + curves[a].first +
                         "' are the same curve: give each sharp curve once");
      }
    }
  }
}

}  // namespace rdmesh::detail
