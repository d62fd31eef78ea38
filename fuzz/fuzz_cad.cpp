// The libFuzzer entry point of the CAD reader (rdmesh::load_cad_file), which
// only reads paths: the bytes go to a temporary file whose extension is
// RDMESH_FUZZ_CAD_EXTENSION (".step" or ".brep"). The file is read as the CLI
// reads it, in an isolated child (CadOptions::isolate): a crash or hang of
// OpenCASCADE must come back as an InputError; anything else is a finding.
// scripts/fuzz.sh runs these targets only when named (a fork per input).
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
