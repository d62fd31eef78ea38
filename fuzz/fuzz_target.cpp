// The libFuzzer entry point of one reader, compiled once per target with
// RDMESH_FUZZ_TARGET naming it (fuzz_inputs.h).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_guard.h"
#include "fuzz_inputs.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  rdmesh::fuzz::expect_success_or_input_error(
      [&] { rdmesh::fuzz::read_input(RDMESH_FUZZ_TARGET, bytes); });
  return 0;
}
