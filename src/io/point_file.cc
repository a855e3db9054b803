// Point files: see point_file.h.
#include "hecal/io/point_file.h"

#include <cctype>
#include <cmath>
#include <map>

#include "hecal/core/error.h"
#include "hecal/io/atomic_file.h"
#include "hecal/io/delimited_text.h"

namespace hecal::io {

namespace {}  // namespace

PointFile ReadPointFile(const std::string& path, std::span<const std::string_view> names,
                        bool lengths, LengthUnit unit, std::string_view what) {
  std::string columns_help = "a header naming id (optional), ";
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) columns_help += ',';  // piece by piece: GCC 12's -Wrestrict false positive (105329)
    columns_help += names[i];
  }
  if (lengths) columns_help += " (with a shared suffix _m or _mm, e.g. x_mm)";

  const std::string text = ReadFile(path);
  LineCursor cursor(text);
  std::string_view line;
  PointFile file;
  file.source = path;
  file.unit = unit;
  std::optional<Separator> separator;
  int id_column = -1;
  std::vector<int> value_columns(names.size(), -1);
  std::size_t column_count = 0;
  std::vector<Field> fields;
  std::string error;
  std::map<std::string, int> id_lines;
  while (cursor.Next(&line)) {
    if (IsBlank(line) || IsComment(line)) continue;
    const int number = cursor.line_number();
    if (!separator) separator = DetectSeparator(line);
    if (!SplitFields(line, *separator, &fields, &error)) {
      throw InputError(path, number, error, "close the quote or remove the text after it");
    }
    if (column_count == 0) {  // the header
      std::optional<std::string> suffix;
      for (std::size_t c = 0; c < fields.size(); ++c) {
        const std::string name = Lowercase(Trim(FieldValue(fields[c])));
        int* slot = nullptr;
        std::string column_suffix;
        if (name == "id") {
          slot = &id_column;
        } else {
          for (std::size_t i = 0; i < names.size() && slot == nullptr; ++i) {
            if (name.rfind(names[i], 0) != 0) continue;
            const std::string rest = name.substr(names[i].size());
            if (rest.empty() || (lengths && (rest == "_m" || rest == "_mm"))) {
              slot = &value_columns[i];
              column_suffix = rest;
            }
          }
        }
        if (slot == nullptr) {
          throw InputError(path, number,
                           "unknown column '" + name + "' in the " + std::string(what) + " header",
                           "write " + columns_help);
        }
        if (*slot >= 0) {
          throw InputError(path, number, "column '" + name + "' appears twice",
                           "keep one column per quantity");
        }
        *slot = static_cast<int>(c);
        if (slot != &id_column) {
          if (suffix && *suffix != column_suffix) {
            throw InputError(path, number, "the position columns have different unit suffixes",
                             "give x, y and z the same suffix (or none)");
          }
          suffix = column_suffix;
        }
      }
      for (std::size_t i = 0; i < names.size(); ++i) {
        if (value_columns[i] < 0) {
          throw InputError(path, number,
                           "the header has no column " + std::string(names[i]) +
                               " (the first non-comment line must be the header)",
                           "write " + columns_help);
        }
      }
      if (suffix && !suffix->empty()) {
        file.unit = *ParseLengthUnit(std::string_view(*suffix).substr(1));
      }
      file.has_ids = id_column >= 0;
      column_count = fields.size();
      continue;
    }
    if (fields.size() != column_count) {
      throw InputError(path, number,
                       "expected " + std::to_string(column_count) + " values, got " +
                           std::to_string(fields.size()),
                       "give one value per header column");
    }
    PointRow row;
    row.line = number;
    for (std::size_t i = 0; i < names.size(); ++i) {
      const Field& field = fields[static_cast<std::size_t>(value_columns[i])];
      double value = 0.0;
      if (!ParseDouble(field.text, &value) || !std::isfinite(value)) {
        throw InputError(
            path, number,
            std::string(names[i]) + " is not a finite number: '" + std::string(field.text) + "'",
            "write a plain decimal number (e.g. 0.125 or -3e-2)");
      }
      row.value(static_cast<Eigen::Index>(i)) = lengths ? value * MetresPer(file.unit) : value;
    }
    if (id_column >= 0) {
      std::string id = std::string(Trim(FieldValue(fields[static_cast<std::size_t>(id_column)])));
      if (id.empty()) throw InputError(path, number, "empty id", "give every row an id");
      const auto [previous, inserted] = id_lines.emplace(id, number);
      if (!inserted) {
        throw InputError(path, number,
                         "id '" + id + "' already used on line " + std::to_string(previous->second),
                         "give every point a unique id");
      }
      row.id = std::move(id);
    }
    file.rows.push_back(std::move(row));
  }
  if (column_count == 0 || file.rows.empty()) {
    throw InputError(path, 0, "no " + std::string(what) + " in the file",
                     "write " + columns_help + ", then one point per line");
  }
  return file;
}

}  // namespace hecal::io
