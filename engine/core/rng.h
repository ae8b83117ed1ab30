#pragma once
// Counter-based random streams: stream k of a stage is Rng(MixSeed(seed, stage, k)), so results do
// not depend on which thread evaluates k or in which order (determinism contract, STYLE B5).

#include <cstdint>

namespace linesurf {

/// Stage tags mixed into seeds so that stages never share a stream.
enum class RngStage : std::uint64_t {
  kDetect = 0x6465746563740001ULL,
  kSynth = 0x73796e7468000002ULL,
  kEvaluate = 0x6576616c00000003ULL,
  kEvidence = 0x6576696400000004ULL,
};

/// SplitMix64 finaliser: a bijective 64-bit mix.
constexpr std::uint64_t Mix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

constexpr std::uint64_t MixSeed(std::uint64_t seed, RngStage stage, std::uint64_t a,
                                std::uint64_t b = 0) {
  return Mix64(Mix64(Mix64(seed ^ static_cast<std::uint64_t>(stage)) ^ a) ^ Mix64(b + 1));
}

/// Small, fast generator (xoshiro256**), seeded through SplitMix64.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) {
    for (auto& s : state_) {
      seed += 0x9E3779B97F4A7C15ULL;
      s = Mix64(seed);
    }
  }
  std::uint64_t NextU64() {
    const std::uint64_t result = Rotl(state_[1] * 5, 7) * 9;
    const std::uint64_t t = state_[1] << 17;
    state_[2] ^= state_[0];
    state_[3] ^= state_[1];
    state_[1] ^= state_[2];
    state_[0] ^= state_[3];
    state_[2] ^= t;
    state_[3] = Rotl(state_[3], 45);
    return result;
  }
  /// Uniform in [0, 1).
  double Uniform() { return static_cast<double>(NextU64() >> 11) * 0x1.0p-53; }
  double Uniform(double lo, double hi) { return lo + (hi - lo) * Uniform(); }
  /// Uniform integer in [0, n); n > 0.
  std::uint64_t Below(std::uint64_t n) {
    __extension__ using Wide = unsigned __int128;  // Lemire's multiply-shift, no modulo bias
    return static_cast<std::uint64_t>((static_cast<Wide>(NextU64()) * n) >> 64);
  }
  /// Standard normal (Box-Muller; deterministic, no cached second value).
  double Normal();

 private:
  static std::uint64_t Rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  std::uint64_t state_[4];
};

}  // namespace linesurf
