// The quality report as JSON and as a terminal summary.
#include <cmath>
#include <cstdio>
#include <string>

#include "rdmesh/quality_report.h"

namespace rdmesh {
namespace {

/// JSON number, or null when not finite (JSON has no infinity).
nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); }

std::string printf_string(const char* format, auto... args) {
  char buf[256];
  std::snprintf(buf, sizeof buf, format, args...);
  return buf;
}

/// "-" for a distance that was not measured, else the value.
std::string distance_text(double d) { return d < 0 ? std::string("-") : printf_string("%.3g", d); }

/// The features line and, when there are curves, one row per curve.
std::string format_features(const QualityReport& r) {
  std::size_t broken = 0, failures = 0;
  for (const CurveStats& c : r.curves) {
    broken += c.is_chain ? 0 : 1;
    failures += c.projection_failures;
  }
  std::string s = printf_string(
      "Features: %zu curves (%zu not a simple chain), %zu of %zu corners, max distance to "
      "curves %s",
      r.curves.size(), broken, r.corners_present, r.corners_expected,
      distance_text(r.feature_max_distance).c_str());
  if (failures > 0) {
    s += printf_string(
        " (%zu sample points not measured: the oracle found no closest point on "
        "their curve, the max distance leaves them out)",
        failures);
  }
  s += '\n';
  if (r.curves.empty()) return s;
  s += printf_string("  %-8s %-24s %12s %6s %12s\n", "curve", "name", "edges", "chain", "max dist");
  for (const CurveStats& c : r.curves) {
    s += printf_string("  %-8d %-24s %12zu %6s %12s\n", c.id.value, c.name.c_str(), c.edges,
                       c.is_chain ? "yes" : "NO", distance_text(c.max_distance).c_str());
  }
  return s;
}

}  // namespace

nlohmann::json to_json(const QualityReport& r) {
  nlohmann::json j;
  j["vertices"] = r.vertices;
  j["tets"] = r.tets;
  j["triangles"] = r.triangles;
  j["min_dihedral_deg"] = number(r.min_dihedral_deg);
  j["max_dihedral_deg"] = number(r.max_dihedral_deg);
  j["max_radius_edge"] = number(r.max_radius_edge);
  j["dihedral_histogram"] = r.dihedral_histogram;
  j["inverted_tets"] = r.inverted_tets;
  j["boundary_max_distance"] = number(r.boundary_max_distance);
  j["boundary_euler_characteristic"] = r.boundary_euler_characteristic;
  j["projection_failures"] = r.projection_failures;
  j["subdomains"] = nlohmann::json::array();
  for (const SubdomainStats& s : r.subdomains) {
    j["subdomains"].push_back(
        {{"id", s.id.value}, {"name", s.name}, {"tets", s.tets}, {"volume", number(s.volume)}});
  }
  j["patches"] = nlohmann::json::array();
  for (const PatchStats& p : r.patches) {
    j["patches"].push_back({{"id", p.id.value},
                            {"name", p.name},
                            {"triangles", p.triangles},
                            {"area", p.area},
                            {"euler_characteristic", p.euler_characteristic},
                            {"max_distance", number(p.max_distance)},
                            {"projection_failures", p.projection_failures}});
  }
  j["curves"] = nlohmann::json::array();
  for (const CurveStats& c : r.curves) {
    j["curves"].push_back({{"id", c.id.value},
                           {"name", c.name},
                           {"edges", c.edges},
                           {"is_chain", c.is_chain},
                           {"max_distance", number(c.max_distance)},
                           {"projection_failures", c.projection_failures}});
  }
  j["corners_present"] = r.corners_present;
  j["corners_expected"] = r.corners_expected;
  j["feature_max_distance"] = number(r.feature_max_distance);
  return j;
}

std::string format_summary(const QualityReport& r) {
  std::string s;
  const bool surface = r.tets == 0;  // a surface-only mesh
  if (surface) {
    s += printf_string("Surface mesh: %zu vertices, %zu triangles\n", r.vertices, r.triangles);
  } else {
    s += printf_string("Mesh: %zu vertices, %zu tetrahedra, %zu boundary triangles\n", r.vertices,
                       r.tets, r.triangles);
    s += printf_string("Dihedral angles: min %.2f deg, max %.2f deg; max radius-edge %.3f\n",
                       r.min_dihedral_deg, r.max_dihedral_deg, r.max_radius_edge);
  }
  if (r.inverted_tets > 0)
    s += printf_string("WARNING: %zu inverted or flat tets\n", r.inverted_tets);
  s += printf_string("Boundary: Euler characteristic %d, max distance to patches %s",
                     r.boundary_euler_characteristic,
                     distance_text(r.boundary_max_distance).c_str());
  if (r.projection_failures > 0) {
    // A sample point (vertex, edge midpoint, centroid) whose closest point the oracle
    // could not find is left out of the max distance: say so, and what it means.
    s += printf_string(
        " (%zu sample points not measured: the oracle found no closest point on "
        "their patch, the max distance leaves them out)",
        r.projection_failures);
  }
  s += '\n';
  if (!surface) {
    s += printf_string("  %-8s %-24s %12s %16s\n", "subdom", "name", "tets", "volume");
    for (const SubdomainStats& d : r.subdomains) {
      s += printf_string("  %-8d %-24s %12zu %16.6g\n", d.id.value, d.name.c_str(), d.tets,
                         d.volume);
    }
  }
  s += printf_string("  %-8s %-24s %12s %6s %12s\n", "patch", "name", "triangles", "euler",
                     "max dist");
  for (const PatchStats& p : r.patches) {
    s += printf_string("  %-8d %-24s %12zu %6d %12s\n", p.id.value, p.name.c_str(), p.triangles,
                       p.euler_characteristic, distance_text(p.max_distance).c_str());
  }
  if (!r.curves.empty() || r.corners_expected > 0) s += format_features(r);
  return s;
}

}  // namespace rdmesh
