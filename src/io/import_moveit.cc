#include "hecal/io/import_moveit.h"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "import_internal.h"

namespace hecal::io {
namespace {

using import_internal::Fail;
using import_internal::Origin;

int LineAtByte(std::string_view text, size_t byte) {
  const size_t end = std::min(byte, text.size());
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + end, '\n'));
}

std::string_view TypeName(const nlohmann::json& value) {
  switch (value.type()) {
    case nlohmann::json::value_t::array:
      return "an array";
    case nlohmann::json::value_t::object:
      return "an object";
    case nlohmann::json::value_t::string:
      return "a string";
    case nlohmann::json::value_t::boolean:
      return "a boolean";
    case nlohmann::json::value_t::null:
      return "null";
    default:
      return "a number";
  }
}

Pose ReadMatrix(const nlohmann::json& matrix, const std::string& source, const std::string& what,
                RotationInput* rotations) {
  constexpr const char* kFix = "write each pose as 4 row arrays of 4 numbers (row-major 4x4)";
  if (!matrix.is_array() || matrix.size() != 4) {
    Fail(source, 0,
         what + " is " + std::string(TypeName(matrix)) +
             (matrix.is_array() ? " of " + std::to_string(matrix.size()) + " rows" : "") +
             ", not a 4x4 matrix",
         kFix);
  }
  double values[16];
  for (size_t r = 0; r < 4; ++r) {
    const nlohmann::json& row = matrix[r];
    if (!row.is_array() || row.size() != 4) {
      Fail(source, 0,
           what + " row " + std::to_string(r) + " is " + std::string(TypeName(row)) +
               (row.is_array() ? " of " + std::to_string(row.size()) + " values" : "") +
               ", not 4 numbers",
           kFix);
    }
    for (size_t c = 0; c < 4; ++c) {
      const nlohmann::json& value = row[c];
      if (!value.is_number()) {
        Fail(source, 0,
             what + " row " + std::to_string(r) + " column " + std::to_string(c) + " is " +
                 std::string(TypeName(value)) + ", not a number",
             "write plain JSON numbers");
      }
      values[4 * r + c] = value.get<double>();
    }
  }
  return import_internal::PoseFromRowMajor(values, 16, 0.0, 1.0, Origin{source, 0, what},
                                           rotations);
}

}  // namespace

ImportedPoses ParseMoveitSamples(std::string_view json_text, const std::string& source) {
  nlohmann::json root;
  try {
    root = nlohmann::json::parse(json_text.begin(), json_text.end());
  } catch (const nlohmann::json::parse_error& e) {
    const std::string message = e.what();
    const size_t colon = message.find(": ");
    Fail(source, LineAtByte(json_text, e.byte > 0 ? e.byte - 1 : 0),
         "not valid JSON: " + (colon == std::string::npos ? message : message.substr(colon + 2)),
         "fix the JSON syntax");
  } catch (const nlohmann::json::exception& e) {
    Fail(source, 0, std::string("not valid JSON: ") + e.what(), "fix the JSON syntax");
  }
  if (!root.is_array()) {
    Fail(source, 1,
         "the file is " + std::string(TypeName(root)) + ", not an array of [M_eef, M_obj] samples",
         "give a MoveIt Calibration pose_samples.json: [[M_eef, M_obj], ...]");
  }
  if (root.empty()) {
    Fail(source, 1, "the file has no samples", "give at least one [M_eef, M_obj] sample");
  }

  ImportedPoses result;
  result.robot = import_internal::MakeTable(source, LengthUnit::kMetre);
  result.camera = import_internal::MakeTable(source, LengthUnit::kMetre);
  RotationInput robot_rotations(source, "robot");
  RotationInput camera_rotations(source, "camera");
  for (size_t i = 0; i < root.size(); ++i) {
    const nlohmann::json& sample = root[i];
    const std::string name = "sample " + std::to_string(i);
    if (!sample.is_array() || sample.size() != 2) {
      Fail(source, 0,
           name + " is " + std::string(TypeName(sample)) +
               (sample.is_array() ? " of " + std::to_string(sample.size()) + " entries" : "") +
               ", not a pair [M_eef, M_obj]",
           "give each sample as [M_eef, M_obj] (two 4x4 matrices)");
    }
    PoseRow robot;
    robot.pose = ReadMatrix(sample[0], source, name + " M_eef", &robot_rotations);
    robot.id = std::to_string(i);
    PoseRow camera;
    camera.pose = ReadMatrix(sample[1], source, name + " M_obj", &camera_rotations);
    camera.id = std::to_string(i);
    result.robot.rows.push_back(std::move(robot));
    result.camera->rows.push_back(std::move(camera));
  }
  result.robot.warnings = robot_rotations.Notes();
  result.camera->warnings = camera_rotations.Notes();

  const std::string format = "format: moveit (MoveIt Calibration pose samples, JSON)";
  result.robot_notes = {
      format,
      "source: " + source,
      import_internal::RobotFrameNote(),
      "convention: sample[i][0] = eef_wrt_world = T_base_eef, used as is (no inverse)",
      import_internal::UnitNote(LengthUnit::kMetre, "as in the source"),
      "id: 0-based sample index in the JSON array"};
  result.camera_notes = {
      format,
      "source: " + source,
      import_internal::CameraFrameNote(),
      "convention: sample[i][1] = obj_wrt_sensor = T_camera_target, used as is (no inverse)",
      import_internal::UnitNote(LengthUnit::kMetre, "as in the source"),
      "id: 0-based sample index in the JSON array"};
  return result;
}

}  // namespace hecal::io
