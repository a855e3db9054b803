#include "hecal/io/import_camodocal.h"

#include <map>

#include "import_internal.h"
#include "import_yaml.h"

namespace hecal::io {
namespace {

using import_internal::Fail;
using import_internal::Origin;

constexpr long kMaxFrames = 1000000;

// "T1_12" → (1, 12); nullopt for other keys.
std::optional<std::pair<int, long>> ParseKey(const std::string& key) {
  if (key.size() < 4 || key[0] != 'T' || (key[1] != '1' && key[1] != '2') || key[2] != '_') {
    return std::nullopt;
  }
  const std::string digits = key.substr(3);
  if (digits.size() > 7 || (digits.size() > 1 && digits[0] == '0')) return std::nullopt;
  long index = 0;
  for (char c : digits) {
    if (c < '0' || c > '9') return std::nullopt;
    index = index * 10 + (c - '0');
  }
  return std::make_pair(key[1] - '0', index);
}

Pose ReadPose(const YAML::Node& node, const std::string& source, const std::string& what,
              RotationInput* rotations) {
  const import_internal::Matrix matrix = import_internal::ReadMatrix(node, source, what);
  const size_t count = matrix.values.size();
  if (!((matrix.rows == 4 && matrix.cols == 4) || (matrix.rows == 3 && matrix.cols == 4) ||
        (matrix.rows == 1 && (count == 16 || count == 12)))) {
    Fail(source, matrix.line,
         what + " is a " + std::to_string(matrix.rows) + "x" + std::to_string(matrix.cols) +
             " matrix, not a 4x4 pose",
         "write T1_i and T2_i as 4x4 homogeneous transforms");
  }
  return import_internal::PoseFromRowMajor(matrix.values.data(), static_cast<int>(count),
                                           RotationRounding(matrix), 1.0,
                                           Origin{source, matrix.line, what}, rotations);
}

ImportedPoses ParseCamodocalYaml(std::string_view yaml_text, const std::string& source) {
  const YAML::Node root = import_internal::LoadYaml(yaml_text, source);
  if (!root.IsMap()) {
    Fail(source, 0, "the file is not a YAML map with frameCount, T1_i and T2_i",
         "give a handeye_calib_camodocal TransformPairsInput.yml");
  }
  const std::optional<YAML::Node> frame_count_node = import_internal::Find(root, "frameCount");
  if (!frame_count_node) {
    Fail(source, 0, "no frameCount",
         "give a handeye_calib_camodocal TransformPairsInput.yml "
         "(frameCount: N, then T1_0, T2_0, ...)");
  }
  const long frame_count =
      import_internal::ScalarCount(*frame_count_node, source, "frameCount", kMaxFrames);

  // Collect T1_i / T2_i by index, whatever their order in the file.
  std::map<long, YAML::Node> poses[2];
  for (auto it = root.begin(); it != root.end(); ++it) {
    if (!it->first.IsScalar()) continue;
    const std::optional<std::pair<int, long>> key = ParseKey(it->first.Scalar());
    if (!key) continue;
    const auto [slot, inserted] = poses[key->first - 1].emplace(key->second, it->second);
    if (!inserted) {
      Fail(source, import_internal::LineOf(it->first), it->first.Scalar() + " appears twice",
           "keep one entry per index");
    }
  }
  for (int which = 0; which < 2; ++which) {
    const std::string prefix = which == 0 ? "T1_" : "T2_";
    if (static_cast<long>(poses[which].size()) != frame_count) {
      Fail(source, import_internal::LineOf(*frame_count_node),
           "frameCount is " + std::to_string(frame_count) + " but the file has " +
               std::to_string(poses[which].size()) + " " + prefix + "i entries",
           "make frameCount equal the number of T1_i/T2_i pairs");
    }
    long expected = 0;
    for (const auto& [index, node] : poses[which]) {
      if (index != expected) {
        Fail(source, import_internal::LineOf(node),
             prefix + std::to_string(expected) + " is missing (found " + prefix +
                 std::to_string(index) + ")",
             "number the entries 0.." + std::to_string(frame_count - 1));
      }
      ++expected;
    }
  }
  if (frame_count == 0) {
    Fail(source, import_internal::LineOf(*frame_count_node), "frameCount is 0: no pose pairs",
         "give at least one T1_i/T2_i pair");
  }

  ImportedPoses result;
  result.robot = import_internal::MakeTable(source, LengthUnit::kMetre);
  result.camera = import_internal::MakeTable(source, LengthUnit::kMetre);
  RotationInput robot_rotations(source, "robot");
  RotationInput camera_rotations(source, "camera");
  for (long i = 0; i < frame_count; ++i) {
    const std::string index = std::to_string(i);
    const YAML::Node& t1 = poses[0].at(i);
    const YAML::Node& t2 = poses[1].at(i);
    PoseRow robot;
    robot.pose = ReadPose(t1, source, "T1_" + index, &robot_rotations);
    robot.id = index;
    robot.line = import_internal::LineOf(t1);
    PoseRow camera;
    camera.pose = ReadPose(t2, source, "T2_" + index, &camera_rotations);
    camera.id = index;
    camera.line = import_internal::LineOf(t2);
    result.robot.rows.push_back(std::move(robot));
    result.camera->rows.push_back(std::move(camera));
  }
  result.robot.warnings = robot_rotations.Notes();
  result.camera->warnings = camera_rotations.Notes();
  const std::string format = "format: camodocal (handeye_calib_camodocal transform pairs)";
  result.robot_notes = {
      format,
      "source: " + source,
      import_internal::RobotFrameNote(),
      "convention: T1_i = lookupTransform(base, ee) = T_base_ee, used as is (no inverse)",
      import_internal::UnitNote(LengthUnit::kMetre, "as in the source"),
      "id: the i of T1_i"};
  result.camera_notes = {
      format,
      "source: " + source,
      import_internal::CameraFrameNote(),
      "convention: T2_i = lookupTransform(camera, marker) = T_camera_marker, used as is (no "
      "inverse)",
      import_internal::UnitNote(LengthUnit::kMetre, "as in the source"),
      "id: the i of T2_i"};
  return result;
}

}  // namespace

ImportedPoses ParseCamodocalPairs(std::string_view yaml_text, const std::string& source) {
  return import_internal::GuardYaml(source, [&] { return ParseCamodocalYaml(yaml_text, source); });
}

}  // namespace hecal::io
