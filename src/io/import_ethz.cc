#include "hecal/io/import_ethz.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>

#include "import_internal.h"

namespace hecal::io {
namespace {

using import_internal::Fail;
using import_internal::Number;
using import_internal::Origin;

// The upstream README writes the layout as a header line "t, x, y, z, q_x, q_y, q_z, q_w"; a
// file that starts with exactly that line (any case, q_x or qx) is accepted.
bool IsLayoutHeader(const std::vector<std::string_view>& tokens) {
  static constexpr const char* kNames[] = {"t", "x", "y", "z", "qx", "qy", "qz", "qw"};
  if (tokens.size() != 8) return false;
  for (size_t k = 0; k < 8; ++k) {
    std::string name;
    for (char c : tokens[k]) {
      if (c == '_') continue;
      name += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    if (name != kNames[k]) return false;
  }
  return true;
}

PoseTable ReadStream(std::string_view text, const std::string& source, bool invert,
                     const std::string& id_prefix) {
  PoseTable table = import_internal::MakeTable(source, LengthUnit::kMetre);
  RotationInput rotations(source);
  bool first = true;
  for (const import_internal::TextLine& line : import_internal::SplitLines(text)) {
    if (import_internal::IsBlankLine(line.text) || import_internal::IsCommentLine(line.text)) {
      continue;
    }
    const std::vector<std::string_view> tokens = import_internal::SplitTokens(line.text);
    if (first && IsLayoutHeader(tokens)) {
      first = false;
      continue;
    }
    first = false;
    if (tokens.size() != 8) {
      Fail(source, line.number,
           "expected 8 numbers (t, x, y, z, qx, qy, qz, qw), found " +
               std::to_string(tokens.size()) + " fields",
           "write one pose per line as t, x, y, z, q_x, q_y, q_z, q_w (no header)");
    }
    const std::vector<Number> v = import_internal::ParseNumbers(tokens, source, line.number);
    if (!std::isfinite(v[0].value)) {
      Fail(source, line.number, "the time stamp is not finite", "write the stamp in seconds");
    }
    double rounding = 0.0;
    for (int k = 4; k < 8; ++k) rounding = std::max(rounding, v[static_cast<size_t>(k)].rounding);
    const Eigen::Vector3d t(v[1].value, v[2].value, v[3].value);
    const Eigen::Vector4d wxyz(v[7].value, v[4].value, v[5].value, v[6].value);
    PoseRow row;
    const Pose pose = import_internal::PoseFromQuaternion(
        t, wxyz, rounding, 1.0,
        Origin{source, line.number, "the pose at t = " + std::string(tokens[0])},
        "q_x, q_y, q_z, q_w (fields 5-8)", &rotations);
    row.pose = invert ? pose.inverse() : pose;
    row.stamp = v[0].value;
    row.id = id_prefix + std::to_string(table.rows.size());
    row.line = line.number;
    table.rows.push_back(std::move(row));
  }
  if (table.rows.empty()) {
    Fail(source, 0, "the file has no poses",
         "give one pose per line: t, x, y, z, q_x, q_y, q_z, q_w");
  }
  table.warnings = rotations.Notes();
  return table;
}

}  // namespace

ImportedPoses ParseEthzStreams(std::string_view robot_text, const std::string& robot_source,
                               std::string_view camera_text, const std::string& camera_source) {
  ImportedPoses result;
  result.robot = ReadStream(robot_text, robot_source, false, "r");
  result.camera = ReadStream(camera_text, camera_source, true, "c");
  result.synchronised = false;
  const std::string format = "format: ethz (ethz-asl hand_eye_calibration pose CSV)";
  const std::string units = import_internal::UnitNote(LengthUnit::kMetre, "as in the source");
  const std::string streams =
      "stamps: seconds as in the source. The robot and camera streams are NOT synchronised "
      "(different rates and lengths); rows are not stations: associate them by stamp before "
      "calibrating";
  result.robot_notes = {
      format,
      "source: " + robot_source,
      import_internal::RobotFrameNote(),
      "convention: the file holds poses_B_H = T_base_hand, used as is (no inverse); quaternion "
      "read in the file's x, y, z, w order",
      units,
      streams,
      "id: r<k>, k the 0-based row of the robot stream (never equal to a camera id)"};
  result.camera_notes = {
      format,
      "source: " + camera_source,
      import_internal::CameraFrameNote(),
      "convention: the file holds poses_W_E = T_target_camera (the camera in the target frame); "
      "each pose was INVERTED to T_camera_target; quaternion read in x, y, z, w order",
      units,
      streams,
      "id: c<k>, k the 0-based row of the camera stream (never equal to a robot id)"};
  return result;
}

}  // namespace hecal::io
