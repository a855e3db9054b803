#include "hecal/io/import_matrix16.h"

#include <algorithm>

#include "import_internal.h"

namespace hecal::io {
namespace {

using import_internal::Fail;
using import_internal::Number;
using import_internal::Origin;

PoseTable ReadMatrices(std::string_view text, const std::string& source, LengthUnit unit) {
  PoseTable table = import_internal::MakeTable(source, unit);
  RotationInput rotations(source);
  const double metres_per_unit = MetresPer(unit);
  for (const import_internal::TextLine& line : import_internal::SplitLines(text)) {
    if (import_internal::IsBlankLine(line.text) || import_internal::IsCommentLine(line.text)) {
      continue;
    }
    const std::vector<std::string_view> tokens = import_internal::SplitTokens(line.text);
    if (tokens.size() != 16 && tokens.size() != 12) {
      Fail(source, line.number,
           "expected 16 numbers (a row-major 4x4 matrix) or 12 (3x4), found " +
               std::to_string(tokens.size()) + " fields",
           "write one pose per line: r11 r12 r13 tx r21 r22 r23 ty r31 r32 r33 tz [0 0 0 1]");
    }
    const std::vector<Number> numbers = import_internal::ParseNumbers(tokens, source, line.number);
    double values[16];
    double rounding = 0.0;
    for (size_t k = 0; k < numbers.size(); ++k) {
      values[k] = numbers[k].value;
      if (k < 12 && k % 4 != 3) rounding = std::max(rounding, numbers[k].rounding);
    }
    PoseRow row;
    row.pose = import_internal::PoseFromRowMajor(
        values, static_cast<int>(numbers.size()), rounding, metres_per_unit,
        Origin{source, line.number, "pose " + std::to_string(table.rows.size())}, &rotations);
    row.id = std::to_string(table.rows.size());
    row.line = line.number;
    table.rows.push_back(std::move(row));
  }
  if (table.rows.empty()) {
    Fail(source, 0, "the file has no poses",
         "give one pose per line as 16 numbers (row-major 4x4)");
  }
  table.warnings = rotations.Notes();
  return table;
}

std::string Convention(const std::string& holds) {
  return "convention: the file is read as " + holds +
         " (hecal's default for matrix16; the file does not say), used as is (no inverse)";
}

}  // namespace

ImportedPoses ParseMatrix16(std::string_view robot_text, const std::string& robot_source,
                            std::optional<std::string_view> camera_text,
                            const std::string& camera_source, const Matrix16Options& options) {
  ImportedPoses result;
  result.robot = ReadMatrices(robot_text, robot_source, options.unit);
  if (camera_text) {
    result.camera = ReadMatrices(*camera_text, camera_source, options.unit);
    if (result.camera->rows.size() != result.robot.rows.size()) {
      Fail(robot_source, 0,
           "has " + std::to_string(result.robot.rows.size()) + " poses but " + camera_source +
               " has " + std::to_string(result.camera->rows.size()),
           "give one camera pose per robot pose (line k of both files is station k)");
    }
  }
  const std::string format = "format: matrix16 (one row-major 4x4 matrix per line)";
  const std::string units = import_internal::UnitNote(
      options.unit, options.unit == LengthUnit::kMetre ? "the default; --units mm for millimetres"
                                                       : "from --units");
  const std::string ids = "id: 0-based pose index (line k of the robot and camera files)";
  result.robot_notes = {format,
                        "source: " + robot_source,
                        import_internal::RobotFrameNote(),
                        Convention("T_base_gripper"),
                        units,
                        ids};
  if (camera_text) {
    result.camera_notes = {format,
                           "source: " + camera_source,
                           import_internal::CameraFrameNote(),
                           Convention("T_camera_target"),
                           units,
                           ids};
  }
  return result;
}

}  // namespace hecal::io
