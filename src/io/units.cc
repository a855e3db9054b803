#include "hecal/io/units.h"

namespace hecal::io {

double MetresPer(LengthUnit unit) {
  return unit == LengthUnit::kMillimetre ? 1e-3 : 1.0;
}

std::optional<LengthUnit> ParseLengthUnit(std::string_view text) {
  if (text == "m") return LengthUnit::kMetre;
  if (text == "mm") return LengthUnit::kMillimetre;
  return std::nullopt;
}

std::string_view UnitName(LengthUnit unit) {
  return unit == LengthUnit::kMillimetre ? "mm" : "m";
}

}  // namespace hecal::io
