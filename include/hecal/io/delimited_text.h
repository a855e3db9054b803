// Low-level reading of delimited text (the pose tables of docs/pose-files.md): lines, fields,
// numbers. Allocation-free on the hot path so that a 100k-row table parses in a few tens of
// milliseconds.
//
// Lines: split at '\n'; a trailing '\r' is dropped (CRLF files), a leading UTF-8 byte-order mark
// is skipped, lines are numbered from 1.
// Fields: a file is either comma-separated (its first non-comment line contains a comma) or
// whitespace-separated (runs of spaces/tabs). Comma-separated fields are trimmed of surrounding
// spaces/tabs, so "1, 2, 3" works. Lines of plain numbers (matrix lines) may use kAny: a comma
// and/or a run of spaces/tabs between fields, so "1, 2\t3 4" is four fields. A field may be
// double-quoted ("a,b"; "" is a quote inside), as RFC 4180 writes it; quoted fields cannot span
// lines. Numbers: std::from_chars (no locale: the decimal separator is always '.'), an optional
// leading
// '+', the whole field must be consumed; "nan"/"inf" parse, so callers check std::isfinite.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace hecal::io {

// Iterates the lines of a text in memory.
class LineCursor {
 public:
  explicit LineCursor(std::string_view text);
  // Stores the next line (without '\n' / "\r\n") and returns true; false after the last line.
  bool Next(std::string_view* line);
  // 1-based number of the line Next() returned last (0 before the first call).
  int line_number() const { return line_number_; }

 private:
  std::string_view text_;
  size_t position_ = 0;
  int line_number_ = 0;
};

// True for a line that is empty or only spaces/tabs.
bool IsBlank(std::string_view line);
// True for a comment line: its first non-space character is '#'.
bool IsComment(std::string_view line);
// The text of a comment line after '#', trimmed.
std::string_view CommentText(std::string_view line);

std::string_view Trim(std::string_view text);
// ASCII letters lowered; every other byte as it is (column names, keys, file extensions).
std::string Lowercase(std::string_view text);

enum class Separator { kComma, kWhitespace, kAny };
// Comma when `first_line` contains a comma, else whitespace.
Separator DetectSeparator(std::string_view first_line);

struct Field {
  std::string_view text;  // without surrounding quotes; "" escapes not yet collapsed
  bool quoted = false;
};

// Splits `line` into `fields` (cleared first). Returns false and sets `*error` for a quote that is
// not closed or text after a closing quote.
bool SplitFields(std::string_view line, Separator separator, std::vector<Field>* fields,
                 std::string* error);

// The field's value with "" collapsed to ".
std::string FieldValue(const Field& field);

// Parses a whole field as a double. Returns false for anything that is not exactly one number
// (empty, trailing text, out of range, quoted text with escapes). NaN and infinities parse.
bool ParseDouble(std::string_view text, double* value);

// Shortest text that reads back as exactly `value` (std::to_chars); -0 is written as 0.
std::string FormatDouble(double value);
// `value` with `decimals` digits after the point (std::fixed), "-" when it is not finite: for
// reports and messages, not for numbers read back.
std::string FormatFixed(double value, int decimals);
// Appends FormatDouble(value) to `out` without a temporary string.
void AppendDouble(double value, std::string* out);

// `value` as one CSV field: quoted (with "" for ") when it contains a comma, a quote, a carriage
// return, leading or trailing whitespace, starts with '#', or is empty; otherwise unchanged.
std::string QuoteField(std::string_view value);

}  // namespace hecal::io
