// The command's CAD layer (rdmesh/cad_layer.h), loaded from
// rdmesh_cad_module.so at the first CAD input: beside the executable in the
// build tree, in LIBDIR/rdmesh once installed (RDMESH_CAD_MODULE_DIR, relative
// to the executable's folder).
#include <dlfcn.h>

#include <atomic>
#include <filesystem>
#include <string>

#include "rdmesh/cad_layer.h"
#include "rdmesh/errors.h"

namespace rdmesh::run {
namespace {
namespace fs = std::filesystem;

constexpr const char* kModule = "rdmesh_cad_module.so";
constexpr const char* kEntry = "rdmesh_cad_layer_v1";
using Entry = const CadLayer* (*)(const char*);

std::atomic<const CadLayer*> loaded{nullptr};

const CadLayer* load_module() {
  std::error_code ec;
  const fs::path dir = fs::read_symlink("/proc/self/exe", ec).parent_path();
  const fs::path candidates[] = {dir / kModule, dir / RDMESH_CAD_MODULE_DIR / kModule};
  for (const fs::path& path : candidates) {
    if (!fs::exists(path, ec)) continue;
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      throw InternalError("CAD support: cannot load " + path.string() + ": " + dlerror());
    }
    const auto entry = reinterpret_cast<Entry>(dlsym(handle, kEntry));
    if (!entry) throw InternalError("CAD support: " + path.string() + " has no " + kEntry);
    const CadLayer* layer = entry(RDMESH_VERSION);
    if (!layer) {
      throw InternalError("CAD support: " + path.string() +
                          " belongs to another version of rdmesh than " RDMESH_VERSION);
    }
    return layer;  // never unloaded: the oracles and size fields it makes run its code
  }
  throw InternalError(std::string("CAD support is not installed: no ") + kModule + " in " +
                      candidates[0].parent_path().string() + " nor in " +
                      candidates[1].parent_path().lexically_normal().string());
}

}  // namespace

const CadLayer& cad_layer() {
  static const CadLayer* const layer = [] {
    const CadLayer* l = load_module();
    loaded.store(l, std::memory_order_release);
    return l;
  }();
  return *layer;
}

const CadLayer* loaded_cad_layer() { return loaded.load(std::memory_order_acquire); }

}  // namespace rdmesh::run
