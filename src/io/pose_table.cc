#include "hecal/io/pose_table.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>

#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/geometry/rotation.h"
#include "hecal/geometry/so3.h"
#include "hecal/io/atomic_file.h"
#include "hecal/io/delimited_text.h"
#include "hecal/io/rotation_input.h"
#include "pose_table_header.h"

namespace hecal::io {
namespace {

using pose_table_internal::EulerDirective;
using pose_table_internal::Group;
using pose_table_internal::Info;
using pose_table_internal::Layout;
using pose_table_internal::ParseHeader;
using pose_table_internal::Quoted;
using pose_table_internal::ToMetres;
using pose_table_internal::ToRadians;

constexpr double kHomogeneousRowTolerance = 1e-9;

class RowParser {
 public:
  explicit RowParser(const std::string& source) : source_(source) {}

  double Number(const Field& field, int line, std::string_view column) const {
    double value = 0.0;
    if (!ParseDouble(field.text, &value)) {
      throw InputError(
          source_, line,
          Quoted(field.text) + " in column " + std::string(column) + " is not a number",
          "write plain decimal numbers with '.' as the decimal point");
    }
    if (!std::isfinite(value)) {
      throw InputError(
          source_, line,
          "non-finite value " + Quoted(field.text) + " in column " + std::string(column),
          "replace NaN/Inf by a real measurement or delete the row");
    }
    return value;
  }

 private:
  const std::string& source_;
};

// The largest PrintedRounding of the given fields.
double LargestRounding(const std::vector<Field>& fields, const int* indices, int count) {
  double rounding = 0.0;
  for (int k = 0; k < count; ++k) {
    rounding = std::max(rounding, PrintedRounding(fields[static_cast<size_t>(indices[k])].text));
  }
  return rounding;
}

void AddNotes(const RotationInput& rotations, PoseTable* table) {
  for (std::string& note : rotations.Notes()) table->warnings.push_back(std::move(note));
}

// Reduces a rotation vector to an angle in [0, 2π) so that so3::Exp never sees an overflowing
// norm; the rotation is unchanged.
Eigen::Vector3d ReducedRotationVector(const Eigen::Vector3d& omega) {
  const double largest = omega.cwiseAbs().maxCoeff();
  if (largest == 0.0) return omega;
  const Eigen::Vector3d scaled = omega / largest;
  const double angle = largest * scaled.norm();
  if (angle <= 2.0 * std::numbers::pi) return omega;
  return std::fmod(angle, 2.0 * std::numbers::pi) * scaled.normalized();
}

void AddRow(PoseRow row, PoseTable* table, std::unordered_map<std::string, int>* id_lines,
            const std::string& source) {
  if (row.id) {
    if (const auto [it, inserted] = id_lines->emplace(*row.id, row.line); !inserted) {
      throw InputError(
          source, row.line,
          "id " + Quoted(*row.id) + " repeats (first at line " + std::to_string(it->second) + ")",
          "give every row its own id");
    }
  }
  table->rows.push_back(std::move(row));
}

void ParseHeaderedRows(LineCursor& cursor, Separator separator, const Layout& layout,
                       int header_line, PoseTable* table) {
  const std::string& source = table->source;
  RowParser parser(source);
  RotationInput rotations(source);
  std::string quaternion_columns;  // as the header names them, for messages
  if (layout.group == Group::kQuaternion || layout.group == Group::kAbb) {
    for (int k = 0; k < 4; ++k) {
      quaternion_columns += (k > 0 ? "," : "") + layout.names[layout.rotation[k]];
    }
  }
  std::unordered_map<std::string, int> id_lines;
  if (layout.id >= 0) id_lines.reserve(table->rows.capacity());
  std::vector<Field> fields;
  std::string split_error;
  std::string_view line;
  while (cursor.Next(&line)) {
    if (IsBlank(line) || IsComment(line)) continue;
    const int number = cursor.line_number();
    if (!SplitFields(line, separator, &fields, &split_error)) {
      throw InputError(source, number, split_error, "close every quote (\"\" inside quotes)");
    }
    if (fields.size() != layout.columns) {
      throw InputError(
          source, number,
          "the row has " + std::to_string(fields.size()) + " values but the header (line " +
              std::to_string(header_line) + ") names " + std::to_string(layout.columns) +
              " columns",
          "give every row one value per header column, separated by " +
              std::string(separator == Separator::kComma ? "commas" : "spaces or tabs"));
    }
    PoseRow row;
    row.line = number;
    if (layout.id >= 0) {
      row.id = FieldValue(fields[layout.id]);
      if (row.id->empty()) {
        throw InputError(source, number, "empty id", "give every row an id, or drop the id column");
      }
    }
    if (layout.stamp >= 0) {
      row.stamp = parser.Number(fields[layout.stamp], number, "stamp");
    }
    Eigen::Vector3d t;
    for (int k = 0; k < 3; ++k) {
      t[k] = ToMetres(
          parser.Number(fields[layout.position[k]], number, layout.names[layout.position[k]]),
          layout.unit);
    }
    double r[9];
    for (int k = 0; k < Info(layout.group).size; ++k) {
      r[k] = parser.Number(fields[layout.rotation[k]], number, layout.names[layout.rotation[k]]);
    }
    Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
    switch (layout.group) {
      case Group::kQuaternion:
      case Group::kAbb:
        R = rotations.Quaternion(Eigen::Vector4d(r[0], r[1], r[2], r[3]),
                                 LargestRounding(fields, layout.rotation.data(), 4),
                                 RotationPlace{number, ""}, quaternion_columns);
        break;
      case Group::kRotationVector: {
        const Eigen::Vector3d omega(ToRadians(r[0], layout.degrees),
                                    ToRadians(r[1], layout.degrees),
                                    ToRadians(r[2], layout.degrees));
        R = so3::Exp(ReducedRotationVector(omega));
        break;
      }
      case Group::kMatrix: {
        Eigen::Matrix3d M;
        M << r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7], r[8];
        R = rotations.Matrix(M, LargestRounding(fields, layout.rotation.data(), 9),
                             RotationPlace{number, ""});
        break;
      }
      case Group::kEuler:
      case Group::kRpy:
      case Group::kKuka:
      case Group::kFanuc: {
        const Eigen::Vector3d angles(ToRadians(r[0], layout.degrees),
                                     ToRadians(r[1], layout.degrees),
                                     ToRadians(r[2], layout.degrees));
        R = MatrixFromEuler(angles, *layout.sequence);
        break;
      }
    }
    row.pose = MakePose(R, t);
    AddRow(std::move(row), table, &id_lines, source);
  }
  AddNotes(rotations, table);
  if (table->rows.empty()) {
    throw InputError(source, header_line, "the file has a header but no poses",
                     "add one row per pose below the header");
  }
}

void ParseMatrixRows(LineCursor& cursor, std::string_view first_line,
                     const PoseReadOptions& options, PoseTable* table) {
  const std::string& source = table->source;
  RowParser parser(source);
  RotationInput rotations(source);
  std::unordered_map<std::string, int> no_ids;
  std::vector<Field> fields;
  std::string split_error;
  std::string_view line = first_line;
  const int first_number = cursor.line_number();
  size_t expected = 0;
  do {
    if (IsBlank(line) || IsComment(line)) continue;
    const int number = cursor.line_number();
    if (!SplitFields(line, Separator::kAny, &fields, &split_error)) {
      throw InputError(source, number, split_error, "write only numbers on matrix lines");
    }
    if (expected == 0) {
      if (fields.size() != 12 && fields.size() != 16) {
        throw InputError(source, number,
                         "a line without a header needs 12 (3×4) or 16 (4×4) numbers, this one "
                         "has " +
                             std::to_string(fields.size()),
                         "write 12 or 16 numbers per line (row-major), or add a header naming "
                         "the columns, e.g. x,y,z,qw,qx,qy,qz");
      }
      expected = fields.size();
    } else if (fields.size() != expected) {
      throw InputError(source, number,
                       "the line has " + std::to_string(fields.size()) + " numbers but line " +
                           std::to_string(first_number) + " has " + std::to_string(expected),
                       "write every pose as " + std::to_string(expected) +
                           " numbers (row-major), one pose per line");
    }
    double m[16];
    for (size_t k = 0; k < fields.size(); ++k) {
      static constexpr std::string_view kNames[16] = {"m11", "m12", "m13", "m14", "m21", "m22",
                                                      "m23", "m24", "m31", "m32", "m33", "m34",
                                                      "m41", "m42", "m43", "m44"};
      m[k] = parser.Number(fields[k], number,
                           std::string(kNames[k]) + " (number " + std::to_string(k + 1) + ")");
    }
    if (expected == 16) {
      const bool homogeneous = std::abs(m[12]) <= kHomogeneousRowTolerance &&
                               std::abs(m[13]) <= kHomogeneousRowTolerance &&
                               std::abs(m[14]) <= kHomogeneousRowTolerance &&
                               std::abs(m[15] - 1.0) <= kHomogeneousRowTolerance;
      if (!homogeneous) {
        // Zeros where a row-major matrix has its translation: the matrix was written by columns.
        const bool column_major = std::abs(m[3]) <= kHomogeneousRowTolerance &&
                                  std::abs(m[7]) <= kHomogeneousRowTolerance &&
                                  std::abs(m[11]) <= kHomogeneousRowTolerance &&
                                  std::abs(m[15] - 1.0) <= kHomogeneousRowTolerance;
        throw InputError(
            source, number,
            "the last row of the 4×4 matrix is " + FormatDouble(m[12]) + " " + FormatDouble(m[13]) +
                " " + FormatDouble(m[14]) + " " + FormatDouble(m[15]) + ", not 0 0 0 1",
            column_major ? "the matrix looks column-major (translation in the last row, as "
                           "Eigen and OpenGL store it); write it row-major (m11 m12 m13 m14 "
                           "= r11 r12 r13 tx, …, last row 0 0 0 1)"
                         : "write a rigid transform (row-major 4×4 with last row 0 0 0 1)");
      }
    }
    Eigen::Matrix3d M;
    M << m[0], m[1], m[2], m[4], m[5], m[6], m[8], m[9], m[10];
    const Eigen::Vector3d t(ToMetres(m[3], options.units), ToMetres(m[7], options.units),
                            ToMetres(m[11], options.units));
    static constexpr int kRotationEntries[9] = {0, 1, 2, 4, 5, 6, 8, 9, 10};
    PoseRow row;
    row.line = number;
    row.pose = MakePose(rotations.Matrix(M, LargestRounding(fields, kRotationEntries, 9),
                                         RotationPlace{number, ""}),
                        t);
    AddRow(std::move(row), table, &no_ids, source);
  } while (cursor.Next(&line));
  AddNotes(rotations, table);
}

}  // namespace

bool PoseReadOptions::IsValid(std::string* why) const {
  if (units != LengthUnit::kMetre && units != LengthUnit::kMillimetre) {
    return Invalid(why, "PoseReadOptions.units", "is not a length unit", "use m or mm");
  }
  return true;
}

PoseTable ParsePoseTable(std::string_view text, const std::string& source,
                         const PoseReadOptions& options) {
  RequireValid(options);
  PoseTable table;
  table.source = source;
  table.unit = options.units;
  table.rows.reserve(static_cast<size_t>(std::count(text.begin(), text.end(), '\n')) + 1);
  LineCursor cursor(text);
  std::string_view line;
  std::optional<EulerSequence> declared_sequence;
  int declared_line = 0;
  bool found = false;
  while (cursor.Next(&line)) {
    if (IsBlank(line)) continue;
    if (IsComment(line)) {
      if (const auto sequence = EulerDirective(line)) {
        if (declared_sequence && *declared_sequence != *sequence) {
          throw InputError(source, cursor.line_number(),
                           "a second Euler sequence " + sequence->ToString() + " (line " +
                               std::to_string(declared_line) + " said " +
                               declared_sequence->ToString() + ")",
                           "keep one '# euler: SEQ' line");
        }
        declared_sequence = sequence;
        declared_line = cursor.line_number();
      }
      continue;
    }
    found = true;
    break;
  }
  if (!found) {
    throw InputError(source, 0, text.empty() ? "the file is empty" : "the file holds no poses",
                     "write a header (e.g. x,y,z,qw,qx,qy,qz) and one row per pose");
  }
  const Separator separator = DetectSeparator(line);
  std::vector<Field> fields;
  std::string split_error;
  if (!SplitFields(line, separator, &fields, &split_error)) {
    throw InputError(source, cursor.line_number(), split_error, "close every quote");
  }
  double unused = 0.0;
  if (!fields.empty() && !fields[0].quoted && ParseDouble(fields[0].text, &unused)) {
    ParseMatrixRows(cursor, line, options, &table);
  } else {
    const int header_line = cursor.line_number();
    const Layout layout = ParseHeader(fields, source, header_line, options, declared_sequence);
    table.unit = layout.unit;
    table.unit_named = layout.unit_named;
    table.rotation = layout.format;
    table.degrees = layout.degrees;
    ParseHeaderedRows(cursor, separator, layout, header_line, &table);
  }
  if (options.invert) {
    for (PoseRow& row : table.rows) row.pose = row.pose.inverse();
  }
  return table;
}

PoseTable ReadPoseTable(const std::string& path, const PoseReadOptions& options) {
  return ParsePoseTable(ReadFile(path), path, options);
}

}  // namespace hecal::io
