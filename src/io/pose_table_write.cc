// FormatPoseTable and WritePoseTable (pose_table.h).
#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>

#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/geometry/rotation.h"
#include "hecal/geometry/so3.h"
#include "hecal/io/atomic_file.h"
#include "hecal/io/delimited_text.h"
#include "hecal/io/pose_table.h"
#include "pose_table_header.h"

namespace hecal::io {
namespace {

using pose_table_internal::FromMetres;
using pose_table_internal::FromRadians;
using pose_table_internal::Quoted;
using pose_table_internal::ToMetres;
using pose_table_internal::ToRadians;

// Appends `scaled` (an internal value converted to the file's unit) as the shortest text that
// converts back to exactly `internal`: 1.00025 m in mm is "1000.25", not "1000.2500000000001",
// so a millimetre or degree file read and written again keeps its digits, and the written text
// still reads back as the same double.
template <typename ToInternal>
void AppendInUnit(double internal, double scaled, ToInternal to_internal, std::string* out) {
  scaled += 0.0;  // -0 → 0
  char buffer[40];
  for (int precision : {15, 16}) {
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof(buffer), scaled,
                                         std::chars_format::general, precision);
    double back = 0.0;
    if (ec == std::errc() && ParseDouble(std::string_view(buffer, end - buffer), &back) &&
        to_internal(back) == internal) {
      out->append(buffer, end);
      return;
    }
  }
  AppendDouble(scaled, out);
}

void CheckFinite(double value, const PoseTable& table, const PoseRow& row, std::string_view what) {
  if (!std::isfinite(value)) {
    throw InputError(table.source, row.line,
                     std::string(what) + " does not fit in a double in the output unit",
                     "write the table in metres");
  }
}

}  // namespace

bool PoseWriteOptions::IsValid(std::string* why) const {
  using Kind = RotationFormat::Kind;
  const Kind kind = rotation.kind;
  if (kind != Kind::kQuaternion && kind != Kind::kRotationVector && kind != Kind::kMatrix &&
      kind != Kind::kEuler) {
    return Invalid(why, "PoseWriteOptions.rotation", "is not a rotation format",
                   "use quaternion, rotvec, matrix or euler:SEQ");
  }
  if (kind == Kind::kEuler && !rotation.sequence) {
    return Invalid(why, "PoseWriteOptions.rotation", "an Euler format needs a sequence",
                   "name the sequence, e.g. xyz");
  }
  if (kind != Kind::kEuler && rotation.sequence) {
    return Invalid(why, "PoseWriteOptions.rotation", "only an Euler format has a sequence",
                   "leave the sequence empty, or use euler:SEQ");
  }
  if (units != LengthUnit::kMetre && units != LengthUnit::kMillimetre) {
    return Invalid(why, "PoseWriteOptions.units", "is not a length unit", "use m or mm");
  }
  return true;
}

std::string FormatPoseTable(const PoseTable& table, const PoseWriteOptions& options) {
  RequireValid(options);
  const RotationFormat& format = options.rotation;
  const bool any_id = std::any_of(table.rows.begin(), table.rows.end(),
                                  [](const PoseRow& row) { return row.id.has_value(); });
  const bool any_stamp = std::any_of(table.rows.begin(), table.rows.end(),
                                     [](const PoseRow& row) { return row.stamp.has_value(); });
  const bool write_id = options.write_id && any_id;
  const bool write_stamp = options.write_stamp && any_stamp;
  const bool has_angles = format.kind == RotationFormat::Kind::kRotationVector ||
                          format.kind == RotationFormat::Kind::kEuler;
  const bool degrees = has_angles && (options.degrees || format.angles_in_degrees);

  std::string out;
  out.reserve(64 + table.rows.size() * (write_id ? 200 : 180));
  for (const std::string& comment : options.comments) {
    size_t begin = 0;
    while (true) {
      const size_t end = comment.find('\n', begin);
      out += "# ";
      out += comment.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
      out += "\n";
      if (end == std::string::npos) break;
      begin = end + 1;
    }
  }
  if (format.kind == RotationFormat::Kind::kEuler && format.preset.empty()) {
    out += "# euler: " + format.sequence->ToString() + "\n";
  }
  // Header: units explicit whenever they are not metres / radians, so the file reads back the
  // same without flags.
  std::vector<std::string> header;
  if (write_id) header.push_back("id");
  if (write_stamp) header.push_back("stamp");
  const std::string length_suffix = options.units == LengthUnit::kMillimetre ? "_mm" : "";
  for (const char* axis : {"x", "y", "z"}) header.push_back(axis + length_suffix);
  const std::string angle_suffix =
      !has_angles ? "" : (degrees ? "_deg" : (format.angles_in_degrees ? "_rad" : ""));
  for (const std::string& name : format.ColumnNames()) header.push_back(name + angle_suffix);
  for (size_t i = 0; i < header.size(); ++i) {
    if (i > 0) out += ',';
    out += header[i];
  }
  out += '\n';

  double values[9];
  for (const PoseRow& row : table.rows) {
    if (write_id) {
      if (!row.id) {
        throw InputError(table.source, row.line, "this row has no id but others do",
                         "give every row an id, or none");
      }
      if (row.id->find('\n') != std::string::npos) {
        throw InputError(table.source, row.line, "id " + Quoted(*row.id) + " contains a line break",
                         "use ids without line breaks");
      }
      out += QuoteField(*row.id);
      out += ',';
    }
    if (write_stamp) {
      if (!row.stamp) {
        throw InputError(table.source, row.line, "this row has no stamp but others do",
                         "give every row a stamp, or none");
      }
      AppendDouble(*row.stamp, &out);
      out += ',';
    }
    const Eigen::Vector3d t = row.pose.translation();
    for (int k = 0; k < 3; ++k) {
      const double value = FromMetres(t[k], options.units);
      CheckFinite(value, table, row, "the position");
      if (options.units == LengthUnit::kMetre) {
        AppendDouble(value, &out);
      } else {
        AppendInUnit(
            t[k], value, [&](double v) { return ToMetres(v, options.units); }, &out);
      }
      out += ',';
    }
    const Eigen::Matrix3d R = row.pose.linear();
    double radians[3] = {0.0, 0.0, 0.0};  // the angles before conversion to degrees
    int count = 0;
    switch (format.kind) {
      case RotationFormat::Kind::kQuaternion: {
        const Eigen::Quaterniond q = QuaternionFromMatrix(R);
        values[0] = q.w();
        values[1] = q.x();
        values[2] = q.y();
        values[3] = q.z();
        count = 4;
        break;
      }
      case RotationFormat::Kind::kRotationVector: {
        const Eigen::Vector3d omega = so3::Log(R);
        for (int k = 0; k < 3; ++k) {
          radians[k] = omega[k];
          values[k] = FromRadians(omega[k], degrees);
        }
        count = 3;
        break;
      }
      case RotationFormat::Kind::kMatrix:
        for (int i = 0; i < 3; ++i) {
          for (int j = 0; j < 3; ++j) values[3 * i + j] = R(i, j);
        }
        count = 9;
        break;
      case RotationFormat::Kind::kEuler: {
        const Eigen::Vector3d angles = EulerFromMatrix(R, *format.sequence);
        for (int k = 0; k < 3; ++k) {
          radians[k] = angles[k];
          values[k] = FromRadians(angles[k], degrees);
        }
        count = 3;
        break;
      }
    }
    for (int k = 0; k < count; ++k) {
      CheckFinite(values[k], table, row, "the rotation");
      if (degrees) {
        AppendInUnit(
            radians[k], values[k], [](double v) { return ToRadians(v, true); }, &out);
      } else {
        AppendDouble(values[k], &out);
      }
      out += k + 1 < count ? ',' : '\n';
    }
  }
  return out;
}

void WritePoseTable(const std::string& path, const PoseTable& table,
                    const PoseWriteOptions& options) {
  WriteFileAtomically(path, FormatPoseTable(table, options));
}

}  // namespace hecal::io
