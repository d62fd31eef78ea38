// The libFuzzer entry point of one reader, compiled once per target with
// RDMESH_FUZZ_TARGET naming it (fuzz_inputs.h). InputError is a clean outcome;
// any other exception aborts with its type and message, so libFuzzer records
// the input as a crash.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string_view>
#include <typeinfo>

#include "fuzz_inputs.h"
#include "rdmesh/errors.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    rdmesh::fuzz::read_input(RDMESH_FUZZ_TARGET,
                             std::string_view(reinterpret_cast<const char*>(data), size));
  } catch (const rdmesh::InputError&) {
    // A rejected input: what the reader must do with bad bytes.
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rdmesh fuzz: %s escaped the reader: %s\n", typeid(e).name(), e.what());
    std::abort();
  } catch (...) {
    std::fprintf(stderr, "rdmesh fuzz: a non-standard exception escaped the reader\n");
    std::abort();
  }
  return 0;
}
