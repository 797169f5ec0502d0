// fuzz_obj.cpp — libFuzzer target for parseObj(): arbitrary bytes must either raise conformesh::InputError or yield a
// valid MeshData that survives writing and re-reading in every format unchanged (fuzz_check.h). Any other exception,
// a sanitizer report, a hang or an out-of-memory is a bug. Built by fuzz/run_fuzzers.sh or fuzz/CMakeLists.txt.
#include <cstddef>
#include <cstdint>
#include <string>

#include "conformesh/intrinsic/io/mesh_io.h"
#include "fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  conformesh::fuzz::fuzzOne(
      data, size, [](const std::string& bytes) { return conformesh::intrinsic::parseObj(bytes, "fuzz.obj"); });
  return 0;
}
