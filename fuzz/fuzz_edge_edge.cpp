// libFuzzer target: edge-edge queries biased to degeneracies (fuzz_input.hpp); checks that
// the filtered method and the exact reference give the same answer and the identical TOI
// (fuzz_check.hpp). Build with -DEXACTCCD_BUILD_FUZZERS=ON and clang; see docs/fuzzing.md.
#include <cstddef>
#include <cstdint>

#include "fuzz/fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  exactccd::fuzzing::fuzz_one<exactccd::EdgeEdgeQuery>(data, size);
  return 0;
}
