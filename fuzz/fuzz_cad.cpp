// The libFuzzer entry point of the CAD reader (rdmesh::load_cad_file), which
// only reads paths: the bytes go to a temporary file whose extension is
// RDMESH_FUZZ_CAD_EXTENSION (".step" or ".brep"). OpenCASCADE reads in this
// process, so its crashes are findings here; scripts/fuzz.sh runs these targets
// only when named, not in CI, until the CAD reading runs in an isolated child.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

#include "fuzz_guard.h"
#include "rdmesh/cad_oracle.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string path =
      "/tmp/rdmesh-fuzz-" + std::to_string(getpid()) + RDMESH_FUZZ_CAD_EXTENSION;
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(data), size);
  rdmesh::fuzz::expect_success_or_input_error([&] { rdmesh::load_cad_file(path); });
  return 0;
}
