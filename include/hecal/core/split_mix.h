// SplitMix64 (Steele, Lea and Flood, "Fast splittable pseudorandom number generators", OOPSLA
// 2014): a bijective, well-mixed 64-bit hash. hecal uses it to derive independent seeds for
// trials, Monte Carlo chunks and render jitter from one user seed, so that results do not
// depend on the number of threads.
#pragma once

#include <cstdint>

namespace hecal {

constexpr std::uint64_t SplitMix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// A uniform number in [0, 1) from the top 53 bits of a hash (every double of that grid equally
// likely).
constexpr double UnitInterval(std::uint64_t bits) {
  return static_cast<double>(bits >> 11) * 0x1.0p-53;
}

}  // namespace hecal
