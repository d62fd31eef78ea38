#include "model_measures.h"

#include "rdmesh/cad_layer.h"
#include "rdmesh/triangle_mesh_oracle.h"

namespace rdmesh::run {
namespace {

ModelMeasures triangle_mesh_measures(const TriangleMeshOracle& tm, bool surface_only) {
  ModelMeasures m;
  const TriangleSoup& soup = tm.mesh();
  const std::vector<PatchId>& patch = tm.triangle_patches();
  for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
    const auto& tri = soup.triangles[t];
    const Point3 &a = soup.points[tri[0]], &b = soup.points[tri[1]], &c = soup.points[tri[2]];
    const std::size_t k = static_cast<std::size_t>(patch[t].value) - 1;
    if (k >= m.patch_area.size()) m.patch_area.resize(k + 1, 0.0);
    m.patch_area[k] += 0.5 * norm(cross(b - a, c - a));
  }
  if (!surface_only) m.total_volume = tm.volume();
  return m;
}

}  // namespace

std::optional<ModelMeasures> model_measures(const DomainOracle& oracle, bool surface_only) {
  if (const CadLayer* cad = cad_layer_of(oracle)) return cad->measures(oracle, surface_only);
  if (const auto* tm = dynamic_cast<const TriangleMeshOracle*>(&oracle)) {
    return triangle_mesh_measures(*tm, surface_only);
  }
  return std::nullopt;
}

}  // namespace rdmesh::run
