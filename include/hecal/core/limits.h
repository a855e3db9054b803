// Resource bounds every job shares (docs/cli.md, "Bounds"): a value above them is refused by the
// options' IsValid (core/options_check.h) before any work, so no option alone can ask for more
// than a workstation has.
#pragma once

#include <cstdint>

namespace hecal {

// Worker threads of a parallel job; 0 means every core.
inline constexpr int kMaxThreads = 256;

// The largest image hecal reads or renders, in pixels (100 megapixels: 10^8 grey bytes).
inline constexpr std::int64_t kMaxImagePixels = 100000000;
// The smallest side of an image hecal reads or renders, in pixels (target detection needs more:
// vision/image_read.h).
inline constexpr int kMinImageSide = 8;

}  // namespace hecal
