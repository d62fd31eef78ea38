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

#include "graded_field.h"
#include "rdmesh/curvature_sizes.h"
#include "rdmesh/errors.h"
#include "rdmesh/mesher.h"
#include "rdmesh/stopwatch.h"

namespace rdmesh {
namespace {

using detail::GradedField;
using detail::Pieces;

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

}  // namespace

EntitySize entity_size(const std::string& key, double size, const DomainOracle& oracle) {
  const auto colon = key.find(':');
  if (colon == std::string::npos) {
    throw InputError(key + ": expected KIND:WHICH, e.g. face:12 (KIND face, curve or solid)");
  }
  if (!(size > 0) || !std::isfinite(size)) {
    throw InputError(key + ": the size must be a positive number");
  }
  const std::string kind = key.substr(0, colon);
  const std::string which = strip_quotes(key.substr(colon + 1));
  EntitySize e;
  e.label = key;
  e.size = size;
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
    throw InputError(key + ": unknown kind '" + kind + "' (expected face, curve or solid)");
  }
  if (e.id == 0) throw InputError(key + ": the domain has no " + kind + " '" + which + "'");
  return e;
}

EntitySize parse_entity_size(const std::string& text, const DomainOracle& oracle) {
  const auto colon = text.find(':'), equals = text.rfind('=');
  if (colon == std::string::npos || equals == std::string::npos || equals < colon) {
    throw InputError("--size-on " + text +
                     ": expected KIND:WHICH=SIZE, e.g. face:12=0.5 (KIND face, curve or solid)");
  }
  double size = -1;
  try {
    std::size_t used = 0;
    const std::string number = text.substr(equals + 1);
    size = std::stod(number, &used);
    if (used != number.size()) size = -1;
  } catch (const std::exception&) {
    size = -1;
  }
  if (!(size > 0) || !std::isfinite(size)) {
    throw InputError("--size-on " + text + ": the size must be a positive number");
  }
  try {
    return entity_size(text.substr(0, equals), size, oracle);
  } catch (const InputError& e) {
    throw InputError("--size-on " + std::string(e.what()));
  }
}

SizeRequests resolve_size_spec(const SizeSpec& spec, const DomainOracle& oracle) {
  SizeRequests r;
  for (const auto& [key, size] : spec.entities)
    r.entities.push_back(entity_size(key, size, oracle));
  if (spec.grade) r.grade = *spec.grade;
  if (spec.curvature) r.curvature = *spec.curvature;
  return r;
}

void merge_size_spec(SizeSpec& into, const SizeSpec& from) {
  into.entities.insert(into.entities.end(), from.entities.begin(), from.entities.end());
  if (from.grade) into.grade = from.grade;
  if (from.curvature) into.curvature = from.curvature;
}

SizesApplied apply_sizes(const DomainOracle& oracle, const SizeRequests& requests,
                         Criteria& criteria) {
  SizesApplied out;
  const std::vector<EntitySize>& sizes = requests.entities;
  if (requests.curvature != 0 && !(requests.curvature > 0 && std::isfinite(requests.curvature))) {
    throw InputError("--curvature must be a positive number of elements per turn");
  }
  if (sizes.empty() && requests.curvature == 0) return out;
  const Stopwatch clock;
  const double grade = requests.grade;
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
  if (!patch_size.empty() || requests.curvature > 0) {
    surface = detail::sampling_surface(oracle, criteria);
  }
  auto near = std::make_shared<GradedField>(grade - 1);
  for (const auto& [patch, size] : patch_size) {
    near->add(patch_pieces(oracle, surface, patch, size), size);
  }
  auto inside = std::make_shared<std::vector<std::pair<int, double>>>();
  for (const EntitySize& e : sizes) {
    if (e.kind == EntitySize::Kind::kCurve) {
      near->add(curve_pieces(oracle, e.id, 0.5 * e.size), e.size);
    } else if (e.kind == EntitySize::Kind::kSubdomain) {
      inside->emplace_back(e.id, e.size);
    }
  }
  if (requests.curvature > 0) {
    out.curvature =
        detail::add_curvature_pieces(oracle, surface, criteria, requests.curvature, *near);
  }
  criteria.edge_size = detail::lowered(criteria.edge_size, near, nullptr, &oracle);
  criteria.facet_size = detail::lowered(criteria.facet_size, near, nullptr, &oracle);
  criteria.cell_size = detail::lowered(criteria.cell_size, near, inside, &oracle);
  out.seconds = clock.seconds();
  return out;
}

void apply_entity_sizes(const DomainOracle& oracle, const std::vector<EntitySize>& sizes,
                        double grade, Criteria& criteria) {
  SizeRequests r;
  r.entities = sizes;
  r.grade = grade;
  if (sizes.empty()) return;
  (void)apply_sizes(oracle, r, criteria);
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
