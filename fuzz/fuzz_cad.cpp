// The libFuzzer entry point of the CAD reader (rdmesh::load_cad_file), which
// only reads paths: the bytes go to a temporary file whose extension is
// RDMESH_FUZZ_CAD_EXTENSION (".step" or ".brep"). OpenCASCADE reads in this
// process, so its crashes are findings here; scripts/fuzz.sh runs these targets
// only with --cad, not in CI, until the CAD reading runs in an isolated child.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <string>
#include <typeinfo>

#include "rdmesh/cad_oracle.h"
#include "rdmesh/errors.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string path = "/tmp/rdmesh-fuzz-" + std::to_string(getpid()) +
                                  RDMESH_FUZZ_CAD_EXTENSION;
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(data), size);
  try {
    rdmesh::load_cad_file(path);
  } catch (const rdmesh::InputError&) {
    // A rejected input: what the reader must do with bad bytes.
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rdmesh fuzz: %s escaped the reader: %s\n", typeid(e).name(), e.what());
    std::abort();
  }
  return 0;
}
