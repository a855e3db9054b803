// Numbers in messages: `value` as an std::ostream prints it with `precision` significant digits,
// the shortest of %g's forms ("100", "0.25", "1e+09").
#pragma once

#include <sstream>
#include <string>

namespace hecal {

inline std::string NumberText(double value, int precision = 6) {
  std::ostringstream text;
  text.precision(precision);
  text << value;
  return text.str();
}

}  // namespace hecal
