// check_fidelity: the mesh against the model's exact measures (see fidelity.h).
#include "rdmesh/fidelity.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "rdmesh/feature_name.h"

namespace rdmesh {
namespace {

std::string format(const char* pattern, double a, double b, double c, double d) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, pattern, a, b, c, d);
  return buffer;
}

/// The sum of facet distance x area over the patches that bound subdomain `id`
/// (all patches for id 0): the model's area, or the mesh's where the model's
/// is unknown.
double allowed_deviation(SubdomainId id, const ModelMeasures& model, const QualityReport& quality,
                         const std::vector<PatchInfo>& patches,
                         const std::vector<double>& facet_distance) {
  const double largest =
      facet_distance.empty() ? 0 : *std::max_element(facet_distance.begin(), facet_distance.end());
  double sum = 0;
  for (const PatchInfo& p : patches) {
    if (id != kOutside && p.side_a != id && p.side_b != id) continue;
    const std::size_t k = static_cast<std::size_t>(p.id.value) - 1;
    const double d = k < facet_distance.size() ? facet_distance[k] : largest;
    if (k < model.patch_area.size()) {
      sum += d * model.patch_area[k];
      continue;
    }
    for (const PatchStats& s : quality.patches) {
      if (s.id == p.id) sum += d * s.area;
    }
  }
  return sum;
}

VolumeCheck compare(SubdomainId id, std::string name, double mesh, double exact, double allowed) {
  VolumeCheck c{id, std::move(name), mesh, exact, 0, true};
  c.tolerance = std::min(allowed, kMaxVolumeDeviation * std::fabs(exact)) + 1e-9 * std::fabs(exact);
  c.passed = std::fabs(mesh - exact) <= c.tolerance;
  return c;
}

}  // namespace

FidelityReport check_fidelity(const QualityReport& quality, const ModelMeasures& model,
                              const std::vector<PatchInfo>& patches,
                              const std::vector<CurveInfo>& curves,
                              const std::vector<double>& facet_distance,
                              const std::vector<CurveId>& below_min_size) {
  FidelityReport r;
  if (!model.subdomain_volume.empty()) {
    for (const SubdomainStats& s : quality.subdomains) {
      const std::size_t k = static_cast<std::size_t>(s.id.value) - 1;
      if (k >= model.subdomain_volume.size()) continue;
      r.volumes.push_back(
          compare(s.id, feature_name(s.id, s.name), s.volume, model.subdomain_volume[k],
                  allowed_deviation(s.id, model, quality, patches, facet_distance)));
    }
  } else if (model.total_volume) {
    double mesh = 0;
    for (const SubdomainStats& s : quality.subdomains) mesh += s.volume;
    r.volumes.push_back(
        compare(kOutside, "the domain", mesh, *model.total_volume,
                allowed_deviation(kOutside, model, quality, patches, facet_distance)));
  }
  for (const VolumeCheck& v : r.volumes) {
    if (v.passed) continue;
    const double scale = std::fabs(v.model_volume) > 0 ? 100 / std::fabs(v.model_volume) : 0;
    r.problems.push_back(v.name + format(": volume %.4g, model %.4g (%+.1f%%, allowed +-%.1f%%)",
                                         v.mesh_volume, v.model_volume,
                                         (v.mesh_volume - v.model_volume) * scale,
                                         v.tolerance * scale));
  }
  std::set<int> unresolved;
  for (const CurveId& c : below_min_size) unresolved.insert(c.value);
  std::set<int> meshed;
  for (const PatchStats& p : quality.patches) {
    if (p.triangles > 0) meshed.insert(p.id.value);
  }
  for (const PatchInfo& p : patches) {
    if (meshed.count(p.id.value)) continue;
    // A face bounded only by curves the protection could not separate from
    // other features (closer than the minimum size) is below it as a whole.
    bool bounded = false, all_below = true;
    for (const CurveInfo& c : curves) {
      if (std::find(c.patches.begin(), c.patches.end(), p.id) == c.patches.end()) continue;
      bounded = true;
      all_below = all_below && unresolved.count(c.id.value) > 0;
    }
    if (bounded && all_below) {
      r.unresolved_patches.push_back(p.id);
      continue;
    }
    r.missing_patches.push_back(p.id);
    r.problems.push_back(feature_name(p.id, p.name) + " has no triangle");
  }
  std::set<int> chained;
  for (const CurveStats& c : quality.curves) {
    if (c.is_chain) chained.insert(c.id.value);
  }
  for (const CurveInfo& c : curves) {
    if (chained.count(c.id.value)) continue;
    if (unresolved.count(c.id.value)) {
      r.unresolved_curves.push_back(c.id);
      continue;
    }
    r.broken_curves.push_back(c.id);
    r.problems.push_back(feature_name(c.id, c.name) + " is not one chain of edges");
  }
  r.passed = r.problems.empty();
  return r;
}

FidelityReport check_fidelity(const QualityReport& quality, const ModelMeasures& model,
                              const std::vector<PatchInfo>& patches,
                              const std::vector<CurveInfo>& curves, double facet_distance,
                              const std::vector<CurveId>& below_min_size) {
  std::size_t n = 0;
  for (const PatchInfo& p : patches) n = std::max(n, static_cast<std::size_t>(p.id.value));
  return check_fidelity(quality, model, patches, curves, std::vector<double>(n, facet_distance),
                        below_min_size);
}

std::vector<double> patch_facet_distances(const TetMesh& mesh, const ScalarField& d) {
  std::vector<double> weighted, area;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const std::size_t k = static_cast<std::size_t>(mesh.triangle_patch[t].value) - 1;
    if (k >= area.size()) {
      area.resize(k + 1, 0.0);
      weighted.resize(k + 1, 0.0);
    }
    const Point3& a = mesh.vertices[static_cast<std::size_t>(mesh.triangles[t][0])];
    const Point3& b = mesh.vertices[static_cast<std::size_t>(mesh.triangles[t][1])];
    const Point3& c = mesh.vertices[static_cast<std::size_t>(mesh.triangles[t][2])];
    const double s = 0.5 * norm(cross(b - a, c - a));
    area[k] += s;
    weighted[k] += s * (d.is_uniform() ? d.constant : d((1.0 / 3) * (a + b + c)));
  }
  std::vector<double> out(area.size(), 0.0);
  double largest = d.is_uniform() ? d.constant : 0.0;
  for (std::size_t k = 0; k < area.size(); ++k) {
    if (area[k] > 0) largest = std::max(largest, out[k] = weighted[k] / area[k]);
  }
  for (std::size_t k = 0; k < area.size(); ++k) {
    if (!(area[k] > 0)) out[k] = largest;
  }
  return out;
}

nlohmann::json to_json(const FidelityReport& r) {
  nlohmann::json j;
  j["passed"] = r.passed;
  j["volumes"] = nlohmann::json::array();
  for (const VolumeCheck& v : r.volumes) {
    j["volumes"].push_back({{"id", v.id.value},
                            {"name", v.name},
                            {"mesh", v.mesh_volume},
                            {"model", v.model_volume},
                            {"tolerance", v.tolerance},
                            {"passed", v.passed}});
  }
  j["missing_patches"] = nlohmann::json::array();
  for (const PatchId& p : r.missing_patches) j["missing_patches"].push_back(p.value);
  j["broken_curves"] = nlohmann::json::array();
  for (const CurveId& c : r.broken_curves) j["broken_curves"].push_back(c.value);
  j["curves_below_min_size"] = nlohmann::json::array();
  for (const CurveId& c : r.unresolved_curves) j["curves_below_min_size"].push_back(c.value);
  j["patches_below_min_size"] = nlohmann::json::array();
  for (const PatchId& p : r.unresolved_patches) j["patches_below_min_size"].push_back(p.value);
  j["problems"] = r.problems;
  return j;
}

std::string summarize_problems(const FidelityReport& report) {
  constexpr std::size_t kShown = 3;
  std::string s;
  for (std::size_t k = 0; k < report.problems.size() && k < kShown; ++k) {
    s += (k ? "; " : "") + report.problems[k];
  }
  if (report.problems.size() > kShown) {
    s += "; and " + std::to_string(report.problems.size() - kShown) + " more";
  }
  return s;
}

}  // namespace rdmesh
