// rdmesh_cad_query_bench: throughput of CadOracle::intersect and ::locate on random queries.
//   rdmesh_cad_query_bench [--count N] [--seconds S] [--dump FILE] [--check] CAD_FILE...
// For each file: N random segments (a third between two random points of the
// bounding box, the rest short ones, length 1e-3..1e-1 x the diagonal, through
// points near the patches' initial points or near the curves, as the duals of
// surface facets are) and N points (a third in the box, the rest near the
// surface or the curves); prints intersect and locate calls
// per second (each measured until N calls or S seconds, whichever comes first). --dump writes one
// line per query ("I k patch x y z" or "I k -", "L k label") so that two builds can be compared
// answer by answer. Uses only the public API: the same source measures any version of the oracle.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "rdmesh/cad_oracle.h"
#include "rdmesh/cad_reference.h"
#include "rdmesh/errors.h"

namespace {

using rdmesh::Point3;
using Clock = std::chrono::steady_clock;

struct Queries {
  std::vector<std::pair<Point3, Point3>> segments;
  std::vector<Point3> points;
};

Queries make_queries(const rdmesh::CadOracle& oracle, int count) {
  const rdmesh::Box3 box = oracle.bounding_box();
  std::vector<Point3> surface;  // the initial points of every patch (independent of intersect)
  for (const rdmesh::PatchInfo& p : oracle.patches()) {
    for (const Point3& x : oracle.initial_points(p.id)) surface.push_back(x);
  }
  std::vector<Point3> edges;  // points of the curves (the faces' boundaries)
  for (const rdmesh::CurveInfo& c : oracle.curves()) {
    for (int k = 0; k < 16; ++k) {
      edges.push_back(oracle.curve(c.id).point(c.t_begin + (c.t_end - c.t_begin) * (k + 0.5) / 16));
    }
  }
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> g(0.0, 1.0);
  auto in_box = [&] {
    return Point3{box.lo.x + u(rng) * (box.hi.x - box.lo.x),
                  box.lo.y + u(rng) * (box.hi.y - box.lo.y),
                  box.lo.z + u(rng) * (box.hi.z - box.lo.z)};
  };
  auto direction = [&] {
    const Point3 v{g(rng), g(rng), g(rng)};
    return (1 / rdmesh::norm(v)) * v;
  };
  const double diag = box.diagonal();
  auto near = [&](const std::vector<Point3>& pts, double scale) {
    const Point3 x = pts[static_cast<std::size_t>(u(rng) * pts.size()) % pts.size()];
    return x + (scale * u(rng)) * direction();
  };
  Queries q;
  for (int i = 0; i < count; ++i) {
    if (i % 3 == 0 || surface.empty()) {  // long: two random points of the box
      q.segments.emplace_back(in_box(), in_box());
      q.points.push_back(in_box());
      continue;
    }
    // Short, through (or near) the surface or its edges, like the dual of a
    // surface facet.
    const std::vector<Point3>& pts = i % 3 == 2 && !edges.empty() ? edges : surface;
    const double len = diag * std::pow(10.0, -1.0 - 2.0 * u(rng));
    const Point3 c = near(pts, 0.2 * len), d = (0.5 * len) * direction();
    q.segments.emplace_back(c - d, c + d);
    q.points.push_back(near(pts, diag * std::pow(10.0, -1.0 - 2.0 * u(rng))));
  }
  return q;
}

/// Agreement of the oracle's nearest crossing with OpenCASCADE's on the segments.
void check(const rdmesh::CadOracle& oracle, const Queries& q) {
  rdmesh::CadReference ref(oracle);
  const double tol = oracle.tolerance();
  int same = 0, none = 0, edge = 0, on_only = 0, we_missed = 0, ref_missed = 0, other = 0;
  int off_face = 0;
  auto valid = [&](const rdmesh::CadOracle::Crossing& c) {
    const auto f = ref.foot(c.point, c.patch);
    return f.distance <= tol && (f.in_face || ref.distance_to_face(c.point, c.patch) <= tol);
  };
  auto show = [&](const char* who, const std::optional<rdmesh::CadOracle::Crossing>& c) {
    if (!c) return std::printf("    %s: none\n", who), void();
    const auto f = ref.foot(c->point, c->patch);
    std::printf("    %s: patch %d at %.9g cos %.3g%s, %.3g off its surface, %.3g off its face\n",
                who, c->patch.value, c->distance, c->cosine, c->tangent ? " tangent" : "",
                f.distance, ref.distance_to_face(c->point, c->patch));
  };
  for (const auto& [a, b] : q.segments) {
    const auto mine = oracle.first_crossing(a, b);
    const auto theirs = ref.first_crossing(a, b);
    if (mine && !valid(*mine)) ++off_face;
    const bool nearer = theirs && (!mine || theirs->distance < mine->distance);
    const char* what = nullptr;
    if (!mine && !theirs) {
      ++none;
    } else if (mine && theirs && rdmesh::distance(mine->point, theirs->point) <= 10 * tol) {
      ++(mine->patch == theirs->patch ? same : edge);
    } else if (nearer && theirs->tangent) {
      ++on_only;  // a segment grazing an edge, within OpenCASCADE's ON band
    } else if (nearer && valid(*theirs)) {
      ++we_missed, what = "missed";
    } else if (mine && !nearer && valid(*mine)) {
      ++ref_missed;
    } else {
      ++other, what = "other";
    }
    if (what) {
      std::printf("  %s: %.17g %.17g %.17g -> %.17g %.17g %.17g\n", what, a.x, a.y, a.z, b.x, b.y,
                  b.z);
      show("oracle", mine);
      show("OpenCASCADE", theirs);
    }
  }
  std::printf(
      "  %zu segments: same %d (none %d), adjacent face %d, OpenCASCADE's ON only %d, "
      "oracle missed %d, OpenCASCADE missed %d, other %d; oracle hits off their face %d\n",
      q.segments.size(), same + none, none, edge, on_only, we_missed, ref_missed, other, off_face);
}

}  // namespace

int main(int argc, char** argv) {
  int count = 20000;
  double seconds = 10;
  std::string dump;
  bool check_mode = false;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--count") && i + 1 < argc) {
      count = std::atoi(argv[++i]);
    } else if (!std::strcmp(argv[i], "--seconds") && i + 1 < argc) {
      seconds = std::atof(argv[++i]);
    } else if (!std::strcmp(argv[i], "--dump") && i + 1 < argc) {
      dump = argv[++i];
    } else if (!std::strcmp(argv[i], "--check")) {
      check_mode = true;
    } else {
      files.push_back(argv[i]);
    }
  }
  if (files.empty()) {
    std::fprintf(
        stderr,
        "usage: rdmesh_cad_query_bench [--count N] [--seconds S] [--dump FILE] CAD_FILE...\n");
    return 2;
  }
  std::FILE* out = dump.empty() ? nullptr : std::fopen(dump.c_str(), "w");
  std::printf("%-40s %8s %12s %12s %8s\n", "file", "load s", "intersect/s", "locate/s", "hits");
  for (const std::string& path : files) {
    const std::string name = path.substr(path.find_last_of('/') + 1);
    try {
      const auto t0 = Clock::now();
      const auto oracle = rdmesh::load_cad_file(path);
      const double load = std::chrono::duration<double>(Clock::now() - t0).count();
      const Queries q = make_queries(*oracle, count);
      if (check_mode) {
        std::printf("%s\n", name.c_str());
        check(*oracle, q);
        continue;
      }
      if (out) std::fprintf(out, "F %s\n", name.c_str());
      int hits = 0, done_i = 0, done_l = 0;
      auto start = Clock::now();
      for (const auto& [a, b] : q.segments) {
        const auto h = oracle->intersect(a, b);
        hits += h.has_value();
        if (out && h) {
          std::fprintf(out, "I %d %d %.17g %.17g %.17g\n", done_i, h->patch.value, h->point.x,
                       h->point.y, h->point.z);
        } else if (out) {
          std::fprintf(out, "I %d -\n", done_i);
        }
        ++done_i;
        if (std::chrono::duration<double>(Clock::now() - start).count() > seconds) break;
      }
      const double ti = std::chrono::duration<double>(Clock::now() - start).count();
      start = Clock::now();
      for (const Point3& p : q.points) {
        const int label = oracle->locate(p).label.value;
        if (out) std::fprintf(out, "L %d %d\n", done_l, label);
        ++done_l;
        if (std::chrono::duration<double>(Clock::now() - start).count() > seconds) break;
      }
      const double tl = std::chrono::duration<double>(Clock::now() - start).count();
      std::printf("%-40s %8.2f %12.0f %12.0f %8d%s\n", name.c_str(), load, done_i / ti, done_l / tl,
                  hits, done_i < count || done_l < count ? "  (time limit)" : "");
      std::fflush(stdout);
    } catch (const rdmesh::Error& e) {
      std::printf("%-40s error: %s\n", name.c_str(), e.what());
    }
  }
  if (out) std::fclose(out);
  return 0;
}
