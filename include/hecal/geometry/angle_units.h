// Degrees and radians. The core works in radians (docs/conventions.md); files, printouts and
// flags speak degrees where their format says so. One pair of factors for every conversion.
#pragma once

#include <numbers>

namespace hecal {

inline constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;
inline constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;

}  // namespace hecal
