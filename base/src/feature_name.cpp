#include "rdmesh/feature_name.h"

namespace rdmesh {
namespace {

std::string named(const char* kind, int id, std::string_view name) {
  std::string out = std::string(kind) + " " + std::to_string(id);
  if (!name.empty()) out.append(" (").append(name).append(")");
  return out;
}

}  // namespace

std::string feature_name(CornerId id) { return named("corner", id.value, {}); }
std::string feature_name(CurveId id, std::string_view name) {
  return named("curve", id.value, name);
}
std::string feature_name(PatchId id, std::string_view name) {
  return named("patch", id.value, name);
}
std::string feature_name(SubdomainId id, std::string_view name) {
  return named("subdomain", id.value, name);
}

}  // namespace rdmesh
