// The run's CAD parts (cad_layer.h) on the cad/ layer.
#include "cad_run_layer.h"

#include "cad_sizes.h"
#include "rdmesh/cad_oracle.h"

namespace rdmesh::run {
namespace {

const CadOracle& as_cad(const DomainOracle& oracle) {
  return dynamic_cast<const CadOracle&>(oracle);
}

class CadRunLayer final : public CadLayer {
 public:
  Loaded load(const std::string& path, bool heal) const override {
    CadOptions options;
    options.heal = heal;
    std::unique_ptr<CadOracle> cad = load_cad_file(path, options);
    Loaded loaded;
    loaded.log = cad->log();
    loaded.warnings = cad->warnings();
    loaded.oracle = std::move(cad);
    return loaded;
  }

  bool is_cad(const DomainOracle& oracle) const override {
    return dynamic_cast<const CadOracle*>(&oracle) != nullptr;
  }

  int follow_thickness(const DomainOracle& cad, Criteria& criteria,
                       FollowedDefaults defaults) const override {
    return run::follow_thickness(as_cad(cad), criteria, defaults);
  }

  /// The volumes only: BRepGProp's face areas cost as much as the rest of the
  /// check on B-spline faces, and the mesh's own areas serve the tolerance.
  ModelMeasures measures(const DomainOracle& oracle, bool surface_only) const override {
    ModelMeasures m;
    if (surface_only) return m;
    const CadOracle& cad = as_cad(oracle);
    for (const SubdomainInfo& s : cad.subdomains()) {
      m.subdomain_volume.resize(static_cast<std::size_t>(s.id.value), 0.0);
      m.subdomain_volume[static_cast<std::size_t>(s.id.value) - 1] = cad.exact_volume(s.id);
    }
    return m;
  }

  std::string patch_color(const DomainOracle& cad, PatchId patch) const override {
    return as_cad(cad).patch_color(patch);
  }
};

}  // namespace

const CadLayer& cad_run_layer() {
  static const CadRunLayer layer;
  return layer;
}

}  // namespace rdmesh::run
