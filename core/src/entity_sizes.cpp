// Sizes per entity (entity_sizes.h): sample points on each entity in a k-d
// tree, the graded size h_e + (grade - 1) x distance folded into the
// criteria by a minimum.
#include "rdmesh/entity_sizes.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <set>

#include "rdmesh/detail/triangle_bvh.h"
#include "rdmesh/errors.h"
#include "rdmesh/mesher.h"

namespace rdmesh {
namespace {

/// A piecewise-linear stand-in of an entity: triangles over a patch, segments
/// (third index -1) along a curve, with their vertices on the entity, in a
/// bounding-volume hierarchy for distance queries.
struct Pieces {
  std::vector<Point3> points;
  std::vector<std::array<int, 3>> items;
};

Point3 closest_on_segment(const Point3& x, const Point3& a, const Point3& b) {
  const Point3 d = b - a;
  const double len2 = squared_norm(d);
  const double t = len2 > 0 ? std::clamp(dot(x - a, d) / len2, 0.0, 1.0) : 0.0;
  return a + t * d;
}

/// One entity's graded size: h + slope x distance to its pieces.
class GradedSize {
 public:
  GradedSize(Pieces pieces, double size, double slope)
      : pieces_(std::move(pieces)), bvh_(boxes(pieces_)), size_(size), slope_(slope) {}
  /// min(bound, h + slope x distance): the search stops where the entity can
  /// no longer lower `bound`.
  double below(const Point3& p, double bound) const {
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

 private:
  static std::vector<Box3> boxes(const Pieces& pieces) {
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
  Pieces pieces_;
  TriangleBvh bvh_;
  double size_, slope_;
};

std::string strip_quotes(std::string s) {
  if (s.size() >= 2 && s.front() == '"' && s.back() == '"') s = s.substr(1, s.size() - 2);
  return s;
}

/// The id whose text or name is `which`, 0 when none.
template <class Info>
int find_entity(const std::vector<Info>& infos, const std::string& which) {
  for (const Info& i : infos) {
    if (std::to_string(i.id.value) == which || i.name == which) return i.id.value;
  }
  return 0;
}

/// The curve as a polyline of chords at most `spacing` of arc long.
Pieces curve_pieces(const DomainOracle& oracle, int id, double spacing) {
  const CurveInfo info = oracle.curves()[id - 1];
  const Curve& c = oracle.curve(CurveId(id));
  Pieces out;
  out.points.push_back(c.point(info.t_begin));
  double t = info.t_begin;
  for (int i = 0; i < 1000000 && t < info.t_end; ++i) {
    t = c.parameter_at_length(t, spacing);
    out.points.push_back(c.point(t));
    const int n = static_cast<int>(out.points.size());
    out.items.push_back({n - 2, n - 1, -1});
  }
  return out;
}

/// The triangles of `patch` in `surface`, each split into sub-triangles at
/// most `spacing` long whose new vertices are projected onto the patch; the
/// oracle's initial points (as degenerate segments) when it has none.
Pieces patch_pieces(const DomainOracle& oracle, const TetMesh& surface, int patch, double spacing) {
  Pieces out;
  for (std::size_t f = 0; f < surface.triangles.size(); ++f) {
    if (surface.triangle_patch[f].value != patch) continue;
    const Point3 &a = surface.vertices[surface.triangles[f][0]],
                 &b = surface.vertices[surface.triangles[f][1]],
                 &c = surface.vertices[surface.triangles[f][2]];
    const double longest = std::max({distance(a, b), distance(b, c), distance(c, a)});
    const int n = std::clamp(static_cast<int>(std::ceil(longest / spacing)), 1, 100);
    const int first = static_cast<int>(out.points.size());
    auto index = [&](int i, int j) { return first + i * (n + 1) - i * (i - 1) / 2 + j; };
    for (int i = 0; i <= n; ++i) {
      for (int j = 0; i + j <= n; ++j) {
        const double u = static_cast<double>(i) / n, v = static_cast<double>(j) / n;
        const Point3 p = (1 - u - v) * a + u * b + v * c;
        const bool vertex = (i == 0 && j == 0) || i == n || j == n;
        const auto q = vertex ? std::optional<Point3>(p) : oracle.project(p, PatchId(patch));
        out.points.push_back(q && distance(*q, p) < longest ? *q : p);
      }
    }
    for (int i = 0; i < n; ++i) {
      for (int j = 0; i + j < n; ++j) {
        out.items.push_back({index(i, j), index(i + 1, j), index(i, j + 1)});
        if (i + j + 1 < n)
          out.items.push_back({index(i + 1, j), index(i + 1, j + 1), index(i, j + 1)});
      }
    }
  }
  if (out.items.empty()) {
    for (const Point3& p : oracle.initial_points(PatchId(patch))) {
      out.points.push_back(p);
      const int k = static_cast<int>(out.points.size()) - 1;
      out.items.push_back({k, k, -1});
    }
  }
  return out;
}

ScalarField lowered(const ScalarField& base,
                    std::shared_ptr<const std::vector<std::unique_ptr<GradedSize>>> near,
                    std::shared_ptr<const std::vector<std::pair<int, double>>> inside,
                    const DomainOracle* oracle) {
  return ScalarField{0.0, [base, near, inside, oracle](const Point3& p) {
                       double h = base(p);
                       for (const auto& g : *near) h = g->below(p, h);
                       if (inside && !inside->empty()) {
                         const int label = oracle->locate(p).value;
                         for (const auto& [id, size] : *inside) {
                           if (id == label) h = std::min(h, size);
                         }
                       }
                       return h;
                     }};
}

}  // namespace

EntitySize parse_entity_size(const std::string& text, const DomainOracle& oracle) {
  const auto colon = text.find(':'), equals = text.rfind('=');
  if (colon == std::string::npos || equals == std::string::npos || equals < colon) {
    throw InputError("--size-on " + text +
                     ": expected KIND:WHICH=SIZE, e.g. face:12=0.5 (KIND face, curve or solid)");
  }
  const std::string kind = text.substr(0, colon);
  const std::string which = strip_quotes(text.substr(colon + 1, equals - colon - 1));
  EntitySize e;
  e.label = text.substr(0, equals);
  try {
    std::size_t used = 0;
    const std::string number = text.substr(equals + 1);
    e.size = std::stod(number, &used);
    if (used != number.size()) e.size = -1;
  } catch (const std::exception&) {
    e.size = -1;
  }
  if (!(e.size > 0) || !std::isfinite(e.size)) {
    throw InputError("--size-on " + text + ": the size must be a positive number");
  }
  if (kind == "face" || kind == "patch") {
    e.kind = EntitySize::Kind::kPatch;
    e.id = find_entity(oracle.patches(), which);
  } else if (kind == "curve" || kind == "edge") {
    e.kind = EntitySize::Kind::kCurve;
    e.id = find_entity(oracle.curves(), which);
  } else if (kind == "solid" || kind == "subdomain") {
    e.kind = EntitySize::Kind::kSubdomain;
    e.id = find_entity(oracle.subdomains(), which);
  } else {
    throw InputError("--size-on " + text + ": unknown kind '" + kind +
                     "' (expected face, curve or solid)");
  }
  if (e.id == 0) {
    throw InputError("--size-on " + text + ": the domain has no " + kind + " '" + which + "'");
  }
  return e;
}

void apply_entity_sizes(const DomainOracle& oracle, const std::vector<EntitySize>& sizes,
                        double grade, Criteria& criteria) {
  if (sizes.empty()) return;
  if (!(grade > 1) || !std::isfinite(grade)) {
    throw InputError("--grade must be a number above 1");
  }
  const double min_size = criteria.min_size_for(oracle.bounding_box());
  for (const EntitySize& e : sizes) {
    if (!(e.size >= min_size)) {
      throw InputError("--size-on " + e.label + ": size below the minimum size (" +
                       std::to_string(min_size) + ")");
    }
  }
  const double slope = grade - 1;
  // Patches (and the patches around a subdomain) are sampled on a first,
  // surface-only mesh at the base sizes.
  std::map<int, double> patch_size;  // patch id -> smallest size asked on or around it
  for (const EntitySize& e : sizes) {
    if (e.kind == EntitySize::Kind::kPatch) {
      auto [it, fresh] = patch_size.emplace(e.id, e.size);
      if (!fresh) it->second = std::min(it->second, e.size);
    } else if (e.kind == EntitySize::Kind::kSubdomain) {
      for (const PatchInfo& p : oracle.patches()) {
        if (p.side_a.value != e.id && p.side_b.value != e.id) continue;
        auto [it, fresh] = patch_size.emplace(p.id.value, e.size);
        if (!fresh) it->second = std::min(it->second, e.size);
      }
    }
  }
  TetMesh surface;
  if (!patch_size.empty()) {
    MeshOptions first;
    first.surface_only = true;
    first.exudation.enabled = false;
    surface = generate_mesh(oracle, criteria, first).mesh;
  }
  auto near = std::make_shared<std::vector<std::unique_ptr<GradedSize>>>();
  for (const auto& [patch, size] : patch_size) {
    near->push_back(
        std::make_unique<GradedSize>(patch_pieces(oracle, surface, patch, size), size, slope));
  }
  auto inside = std::make_shared<std::vector<std::pair<int, double>>>();
  for (const EntitySize& e : sizes) {
    if (e.kind == EntitySize::Kind::kCurve) {
      near->push_back(
          std::make_unique<GradedSize>(curve_pieces(oracle, e.id, 0.5 * e.size), e.size, slope));
    } else if (e.kind == EntitySize::Kind::kSubdomain) {
      inside->emplace_back(e.id, e.size);
    }
  }
  criteria.edge_size = lowered(criteria.edge_size, near, nullptr, &oracle);
  criteria.facet_size = lowered(criteria.facet_size, near, nullptr, &oracle);
  criteria.cell_size = lowered(criteria.cell_size, near, inside, &oracle);
}

std::vector<AchievedSize> achieved_sizes(const TetMesh& mesh,
                                         const std::vector<EntitySize>& sizes) {
  std::vector<AchievedSize> out;
  for (const EntitySize& e : sizes) {
    std::set<std::pair<int, int>> edges;
    auto add = [&](int a, int b) { edges.insert(std::minmax(a, b)); };
    if (e.kind == EntitySize::Kind::kPatch) {
      for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
        if (mesh.triangle_patch[f].value != e.id) continue;
        const auto& t = mesh.triangles[f];
        add(t[0], t[1]), add(t[1], t[2]), add(t[2], t[0]);
      }
    } else if (e.kind == EntitySize::Kind::kCurve) {
      for (std::size_t k = 0; k < mesh.edges.size(); ++k) {
        if (mesh.edge_curve[k].value == e.id) add(mesh.edges[k][0], mesh.edges[k][1]);
      }
    } else {
      for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
        if (mesh.tet_subdomain[t].value != e.id) continue;
        const auto& v = mesh.tets[t];
        for (int i = 0; i < 4; ++i) {
          for (int j = i + 1; j < 4; ++j) add(v[i], v[j]);
        }
      }
    }
    AchievedSize a{e, edges.size(), 0, 0};
    for (const auto& [i, j] : edges) {
      const double l = distance(mesh.vertices[i], mesh.vertices[j]);
      a.mean_edge += l;
      a.max_edge = std::max(a.max_edge, l);
    }
    if (!edges.empty()) a.mean_edge /= static_cast<double>(edges.size());
    out.push_back(a);
  }
  return out;
}

}  // namespace rdmesh
