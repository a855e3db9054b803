#include "hecal/io/delimited_text.h"

#include <charconv>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <system_error>

namespace hecal::io {
namespace {

constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";

bool IsSpace(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

}  // namespace

LineCursor::LineCursor(std::string_view text) : text_(text) {
  if (text_.starts_with(kByteOrderMark)) position_ = kByteOrderMark.size();
}

bool LineCursor::Next(std::string_view* line) {
  if (position_ >= text_.size()) return false;
  const size_t end = text_.find('\n', position_);
  const size_t stop = end == std::string_view::npos ? text_.size() : end;
  std::string_view result = text_.substr(position_, stop - position_);
  if (!result.empty() && result.back() == '\r') result.remove_suffix(1);
  position_ = end == std::string_view::npos ? text_.size() : end + 1;
  ++line_number_;
  *line = result;
  return true;
}

std::string_view Trim(std::string_view text) {
  size_t begin = 0;
  while (begin < text.size() && IsSpace(text[begin])) ++begin;
  size_t end = text.size();
  while (end > begin && IsSpace(text[end - 1])) --end;
  return text.substr(begin, end - begin);
}

std::string Lowercase(std::string_view text) {
  std::string lower(text);
  for (char& c : lower) {
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  }
  return lower;
}

bool IsBlank(std::string_view line) {
  return Trim(line).empty();
}

bool IsComment(std::string_view line) {
  const std::string_view trimmed = Trim(line);
  return !trimmed.empty() && trimmed.front() == '#';
}

std::string_view CommentText(std::string_view line) {
  std::string_view trimmed = Trim(line);
  if (!trimmed.empty() && trimmed.front() == '#') trimmed.remove_prefix(1);
  return Trim(trimmed);
}

Separator DetectSeparator(std::string_view first_line) {
  return first_line.find(',') == std::string_view::npos ? Separator::kWhitespace
                                                        : Separator::kComma;
}

bool SplitFields(std::string_view line, Separator separator, std::vector<Field>* fields,
                 std::string* error) {
  fields->clear();
  const size_t n = line.size();
  size_t i = 0;
  if (separator != Separator::kComma) {
    while (i < n && IsSpace(line[i])) ++i;
    if (i == n) return true;  // no fields
  }
  while (true) {
    // At the start of a field: skip leading blanks (comma mode; whitespace mode is already there).
    while (i < n && IsSpace(line[i])) ++i;
    Field field;
    if (i < n && line[i] == '"') {
      field.quoted = true;
      const size_t begin = ++i;
      while (true) {
        if (i >= n) {
          *error = "a quote (\") opened in field " + std::to_string(fields->size() + 1) +
                   " is not closed";
          return false;
        }
        if (line[i] == '"') {
          if (i + 1 < n && line[i + 1] == '"') {
            i += 2;  // escaped quote
            continue;
          }
          break;
        }
        ++i;
      }
      field.text = line.substr(begin, i - begin);
      ++i;  // closing quote
      while (i < n && IsSpace(line[i])) ++i;
      const bool after_space = i > 0 && IsSpace(line[i - 1]);
      const bool at_separator = i == n || (separator != Separator::kWhitespace && line[i] == ',') ||
                                (separator != Separator::kComma && after_space);
      if (!at_separator) {
        *error = "text after the closing quote of field " + std::to_string(fields->size() + 1);
        return false;
      }
    } else {
      const size_t begin = i;
      if (separator == Separator::kComma) {
        while (i < n && line[i] != ',') ++i;
        field.text = Trim(line.substr(begin, i - begin));
      } else if (separator == Separator::kAny) {
        while (i < n && line[i] != ',' && !IsSpace(line[i])) ++i;
        field.text = line.substr(begin, i - begin);
        while (i < n && IsSpace(line[i])) ++i;
      } else {
        while (i < n && !IsSpace(line[i])) ++i;
        field.text = line.substr(begin, i - begin);
        while (i < n && IsSpace(line[i])) ++i;
      }
    }
    fields->push_back(field);
    if (i >= n) return true;
    if (separator != Separator::kWhitespace && line[i] == ',') {
      ++i;  // the comma; a trailing comma adds an empty field
      if (i == n) {
        fields->push_back(Field{});
        return true;
      }
    }
  }
}

std::string FieldValue(const Field& field) {
  if (!field.quoted) return std::string(field.text);
  std::string value;
  value.reserve(field.text.size());
  for (size_t i = 0; i < field.text.size(); ++i) {
    value.push_back(field.text[i]);
    if (field.text[i] == '"' && i + 1 < field.text.size() && field.text[i + 1] == '"') ++i;
  }
  return value;
}

bool ParseDouble(std::string_view text, double* value) {
  if (text.size() > 1 && text.front() == '+' && text[1] != '-' && text[1] != '+') {
    text.remove_prefix(1);
  }
  if (text.empty()) return false;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, *value, std::chars_format::general);
  return ec == std::errc() && ptr == end;
}

void AppendDouble(double value, std::string* out) {
  char buffer[32];
  const auto [ptr, ec] = std::to_chars(buffer, buffer + sizeof(buffer), value + 0.0);
  // 32 characters always suffice for the shortest round-trip form of a double.
  out->append(buffer, ec == std::errc() ? ptr : buffer);
}

std::string FormatDouble(double value) {
  std::string text;
  AppendDouble(value, &text);
  return text;
}

std::string FormatFixed(double value, int decimals) {
  if (!std::isfinite(value)) return "-";
  std::ostringstream text;
  text << std::fixed << std::setprecision(decimals) << value;
  return text.str();
}

std::string QuoteField(std::string_view value) {
  const bool needs_quotes = value.empty() || value.front() == '#' || IsSpace(value.front()) ||
                            IsSpace(value.back()) ||
                            value.find_first_of(",\"\r") != std::string_view::npos;
  if (!needs_quotes) return std::string(value);
  std::string quoted = "\"";
  for (char c : value) {
    if (c == '"') quoted.push_back('"');
    quoted.push_back(c);
  }
  quoted.push_back('"');
  return quoted;
}

}  // namespace hecal::io
