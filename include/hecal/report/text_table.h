// Cells of the plain-text tables hecal prints (study_text.h): padding to a column width and the
// number formats the tables share. Pure functions of their arguments.
#pragma once

#include <cstddef>
#include <string>

namespace hecal::report {

// `text` padded with spaces to `width` (right-aligned, or left-aligned); longer text is kept.
std::string Pad(const std::string& text, std::size_t width, bool left_align = false);

// One value through printf's `format` ("%.2f", "%.1fx"); at most 47 characters.
std::string Printf(const char* format, double value);

// io::FormatFixed (`precision` digits after the point); a value that is not finite as
// study::FormatNumber writes it ("nan", "inf", "-inf"), not as "-".
std::string Fixed(double value, int precision);

// Fixed(value, 4) for ordinary magnitudes, "%.2e" for the tiny non-zero errors of noise-free
// data (|value| < 1e-3).
std::string Readable(double value);

}  // namespace hecal::report
