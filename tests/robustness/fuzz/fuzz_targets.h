#pragma once
// The fuzz targets of the readers (docs/design/sanitizers_and_fuzzing.md): one entry point per
// reader, shared by the libFuzzer executables (fuzz_main.cpp) and by the corpus replay test that
// runs in the normal CTest suite (fuzz_replay_test.cpp).

#include <cstddef>
#include <cstdint>
#include <span>

namespace linesurf::fuzz {

/// One reader under test. `run` writes the bytes to a file of the reader's extension, reads it
/// and returns 0. Malformed input must end in a clear error (invalid_input and the like); an
/// internal error or an exception of another kind is a finding and aborts the process.
struct FuzzTarget {
  const char* name;  ///< also the corpus directory: tests/robustness/fuzz/corpus/<name>/
  int (*run)(const std::uint8_t* data, std::size_t size);
};

/// Every target, in a fixed order.
[[nodiscard]] std::span<const FuzzTarget> FuzzTargets();

/// The target named `name`; aborts when there is none (a build error of a fuzz executable).
[[nodiscard]] const FuzzTarget& FindFuzzTarget(const char* name);

}  // namespace linesurf::fuzz
