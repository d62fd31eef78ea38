// The run's CAD parts behind one interface (run/src/cad/cad_run_layer.cpp), so that
// the command loads OpenCASCADE only for a CAD input.
//
// OpenCASCADE's 28 libraries cost every process that links them about 50 ms at
// start (the dynamic loader resolves some 100 k symbol relocations; Debian
// builds them with immediate binding): as much as a 150 k-tet implicit run's
// refinement on two threads. The command (cli/) therefore links no CAD: the
// first CAD input loads rdmesh_cad_module.so, which holds these parts and the
// cad/ layer, with dlopen (cli/cad_module_loader.cpp). The Python module, the
// tests link them (run/src/cad/linked_cad_layer.cpp). Either way
// exactly one of the two defines the functions below.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "rdmesh/criteria.h"
#include "rdmesh/fidelity.h"
#include "rdmesh/oracle.h"

namespace rdmesh::run {

/// Which defaults of a CAD run follow the thickness of slender parts
/// (run/src/cad/cad_sizes.h): those the user did not set.
struct FollowedDefaults {
  bool facet_distance = true;
  bool min_size = true;
};

class CadLayer {
 public:
  virtual ~CadLayer() = default;

  struct Loaded {
    std::unique_ptr<DomainOracle> oracle;
    std::vector<std::string> log;       ///< what healing changed (with `heal`)
    std::vector<std::string> warnings;  ///< what the user should know about the model
  };
  /// load_cad_file (cad_oracle.h), healed first with `heal`. Throws InputError.
  virtual Loaded load(const std::string& path, bool heal) const = 0;
  /// Whether `oracle` is a CAD model (a CadOracle).
  virtual bool is_cad(const DomainOracle& oracle) const = 0;
  /// The following functions take a CAD model (is_cad).
  /// Default sizes lowered near slender parts (run/src/cad/cad_sizes.h); returns the
  /// number of faces that lowered them.
  virtual int follow_thickness(const DomainOracle& cad, Criteria& criteria,
                               FollowedDefaults defaults) const = 0;
  /// The exact volumes per subdomain (BRepGProp), none with `surface_only`.
  virtual ModelMeasures measures(const DomainOracle& cad, bool surface_only) const = 0;
  /// The colour the file gives a face, "#rrggbb", or empty.
  virtual std::string patch_color(const DomainOracle& cad, PatchId patch) const = 0;
};

/// The CAD layer, loaded on the first call where it is a module. Throws
/// InternalError when the module cannot be loaded (an incomplete installation).
const CadLayer& cad_layer();

/// The CAD layer if it is loaded already, else nullptr: no oracle can then be a
/// CAD model, and asking costs no loading.
const CadLayer* loaded_cad_layer();

/// Whether `oracle` is a CAD model: loaded_cad_layer()->is_cad(oracle).
inline const CadLayer* cad_layer_of(const DomainOracle& oracle) {
  const CadLayer* layer = loaded_cad_layer();
  return layer && layer->is_cad(oracle) ? layer : nullptr;
}

}  // namespace rdmesh::run
