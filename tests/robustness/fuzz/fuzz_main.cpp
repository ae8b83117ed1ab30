// libFuzzer entry of one reader; built once per target with LINESURF_FUZZ_TARGET_NAME set
// (tests/robustness/fuzz/CMakeLists.txt).

#include "tests/robustness/fuzz/fuzz_targets.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const linesurf::fuzz::FuzzTarget& target =
      linesurf::fuzz::FindFuzzTarget(LINESURF_FUZZ_TARGET_NAME);
  return target.run(data, size);
}
