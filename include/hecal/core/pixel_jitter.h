// Stratified, jittered sample positions inside a pixel, for area anti-aliasing by supersampling
// (vision/render.h, and the textured-plane renderer of the tests). Sample (a, b) of the s × s
// grid of pixel (i, j) lies at the fraction ((a + u)/s, (b + v)/s) of the pixel, with u and v in
// [0, 1) drawn by SplitMix64 (core/split_mix.h) from the pixel's position and the sample's index:
// the same image on every run and thread count, and no systematic bias along straight edges
// (the area integral of a straight edge is unbiased, vision/render_test).
#pragma once

#include <cstdint>

#include "hecal/core/split_mix.h"

namespace hecal {

// The key of pixel (i, j) (column, row) from which its samples' jitter is drawn.
inline std::uint64_t PixelKey(int i, int j) {
  return SplitMix64(static_cast<std::uint64_t>(j) * 0x100000001b3ULL +
                    static_cast<std::uint64_t>(i));
}

struct PixelFraction {
  double x = 0.0;  // along the pixel's columns, 0 … 1
  double y = 0.0;  // along its rows, 0 … 1
};

// Sample (a, b), 0 ≤ a, b < s, of the pixel whose key is `pixel_key`.
inline PixelFraction JitteredSample(std::uint64_t pixel_key, int a, int b, int s) {
  const std::uint64_t h = SplitMix64(pixel_key + static_cast<std::uint64_t>(b * s + a));
  return {(a + UnitInterval(h)) / s, (b + UnitInterval(SplitMix64(h))) / s};
}

}  // namespace hecal
