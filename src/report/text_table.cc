// Cells of the plain-text tables: see text_table.h.
#include "hecal/report/text_table.h"

#include <cmath>
#include <cstdio>

#include "hecal/io/delimited_text.h"
#include "hecal/study/study_csv.h"

namespace hecal::report {

std::string Pad(const std::string& text, std::size_t width, bool left_align) {
  if (text.size() >= width) return text;
  const std::string padding(width - text.size(), ' ');
  return left_align ? text + padding : padding + text;
}

std::string Printf(const char* format, double value) {
  char buffer[48];
  std::snprintf(buffer, sizeof(buffer), format, value);
  return buffer;
}

std::string Fixed(double value, int precision) {
  return std::isfinite(value) ? io::FormatFixed(value, precision) : study::FormatNumber(value);
}

std::string Readable(double value) {
  if (std::isfinite(value) && value != 0.0 && std::abs(value) < 1e-3) {
    return Printf("%.2e", value);
  }
  return Fixed(value, 4);
}

}  // namespace hecal::report
