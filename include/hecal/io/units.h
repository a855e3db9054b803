// Length units of files (docs/conventions.md). The core works in metres; files say their unit in
// the header suffix (x_mm) or by the --units flag, and results are written back in the input's
// unit.
#pragma once

#include <optional>
#include <string_view>

namespace hecal::io {

enum class LengthUnit { kMetre, kMillimetre };

// Metres per unit: 1 for m, 0.001 for mm.
double MetresPer(LengthUnit unit);
// "m" | "mm" → unit; nullopt otherwise.
std::optional<LengthUnit> ParseLengthUnit(std::string_view text);
std::string_view UnitName(LengthUnit unit);

}  // namespace hecal::io
