#include "hecal/io/import_opencv_yaml.h"

#include <set>

#include "import_internal.h"
#include "import_yaml.h"

namespace hecal::io {
namespace {

using import_internal::Fail;
using import_internal::Find;
using import_internal::LineOf;
using import_internal::Origin;

constexpr const char* kLayoutFix =
    "give R_gripper2base, t_gripper2base, R_target2cam, t_target2cam (or T_gripper2base, "
    "T_target2cam) as lists of matrices; see docs/import-formats.md";

// One way a pose list can be written: its key names and whether the file holds the inverse of
// hecal's pose.
struct Spelling {
  const char* rotation;     // R_... (nullptr: only the 4×4 key)
  const char* translation;  // t_...
  const char* matrix;       // T_...
  bool inverse;
  const char* meaning;  // for the header note
};

constexpr Spelling kRobotSpellings[] = {
    {"R_gripper2base", "t_gripper2base", "T_gripper2base", false,
     "gripper2base = T_base_gripper, used as is (no inverse)"},
    {"R_base2gripper", "t_base2gripper", "T_base2gripper", true,
     "base2gripper = T_gripper_base, INVERTED to T_base_gripper"},
};

constexpr Spelling kCameraSpellings[] = {
    {"R_target2cam", "t_target2cam", "T_target2cam", false,
     "target2cam = T_camera_target, used as is (no inverse)"},
    {"R_world2cam", "t_world2cam", "T_world2cam", false,
     "world2cam = T_camera_target, used as is (no inverse)"},
    {"R_cam2target", "t_cam2target", "T_cam2target", true,
     "cam2target = T_target_camera, INVERTED to T_camera_target"},
    {"R_cam2world", "t_cam2world", "T_cam2world", true,
     "cam2world = T_target_camera, INVERTED to T_camera_target"},
};

const YAML::Node& RequireList(const YAML::Node& node, const std::string& source,
                              const std::string& key) {
  if (!node.IsSequence()) {
    Fail(source, LineOf(node), key + " is not a list of matrices",
         "write " + key + " as a YAML list (one entry per station)");
  }
  return node;
}

Eigen::Vector3d ReadVector3(const YAML::Node& node, const std::string& source,
                            const std::string& what) {
  const import_internal::Matrix m = import_internal::ReadMatrix(node, source, what);
  if (m.values.size() != 3 || !(m.rows == 1 || m.cols == 1)) {
    Fail(source, m.line,
         what + " is " + std::to_string(m.rows) + "x" + std::to_string(m.cols) + ", not a 3-vector",
         "write it as a 3x1 matrix");
  }
  return Eigen::Vector3d(m.values[0], m.values[1], m.values[2]);
}

Pose ReadRotationAndTranslation(const YAML::Node& rotation, const YAML::Node& translation,
                                double metres_per_unit, const std::string& source,
                                const std::string& what, RotationInput* rotations) {
  const import_internal::Matrix r = import_internal::ReadMatrix(rotation, source, what + " R");
  const Eigen::Vector3d t = ReadVector3(translation, source, what + " t");
  const Origin origin{source, r.line, what};
  if (r.values.size() == 9 && ((r.rows == 3 && r.cols == 3) || r.rows == 1)) {
    return import_internal::PoseFromRotationAndTranslation(r.values.data(), t.data(),
                                                           import_internal::RotationRounding(r),
                                                           metres_per_unit, origin, rotations);
  }
  if (r.values.size() == 3 && (r.rows == 1 || r.cols == 1)) {
    return import_internal::PoseFromRotationVector(
        Eigen::Vector3d(r.values[0], r.values[1], r.values[2]), t, metres_per_unit, origin);
  }
  Fail(source, r.line,
       what + " R is " + std::to_string(r.rows) + "x" + std::to_string(r.cols) +
           ", neither a 3x3 rotation matrix nor a 3x1 rotation vector",
       "write each rotation as a 3x3 matrix or a 3x1 Rodrigues vector");
}

Pose ReadHomogeneous(const YAML::Node& node, double metres_per_unit, const std::string& source,
                     const std::string& what, RotationInput* rotations) {
  const import_internal::Matrix m = import_internal::ReadMatrix(node, source, what);
  const size_t count = m.values.size();
  if (!((m.cols == 4 && (m.rows == 4 || m.rows == 3)) ||
        (m.rows == 1 && (count == 16 || count == 12)))) {
    Fail(source, m.line,
         what + " is " + std::to_string(m.rows) + "x" + std::to_string(m.cols) +
             ", not a 4x4 or 3x4 transform",
         "write each T_ entry as a 4x4 homogeneous matrix");
  }
  return import_internal::PoseFromRowMajor(m.values.data(), static_cast<int>(count),
                                           import_internal::RotationRounding(m), metres_per_unit,
                                           Origin{source, m.line, what}, rotations);
}

struct PoseList {
  std::vector<Pose> poses;
  std::vector<int> lines;
  std::vector<std::string> notes;  // RotationInput::Notes() of the list
  const Spelling* spelling = nullptr;
  std::string keys;  // the keys used, for messages and notes
};

template <size_t N>
PoseList ReadPoseList(const YAML::Node& root, const Spelling (&spellings)[N],
                      double metres_per_unit, const std::string& source, const char* role) {
  PoseList list;
  RotationInput rotation_input(source, role);
  for (const Spelling& spelling : spellings) {
    const std::optional<YAML::Node> rotation = Find(root, spelling.rotation);
    const std::optional<YAML::Node> translation = Find(root, spelling.translation);
    const std::optional<YAML::Node> matrix = Find(root, spelling.matrix);
    if (!rotation && !translation && !matrix) continue;
    std::string keys;
    if (rotation || translation) keys = std::string(spelling.rotation) + "/" + spelling.translation;
    if (matrix) keys += (keys.empty() ? "" : " and ") + std::string(spelling.matrix);
    if (list.spelling != nullptr) {
      Fail(source, 0,
           "the " + std::string(role) + " poses are given twice: " + list.keys + " and " + keys,
           "keep one of them");
    }
    list.spelling = &spelling;
    list.keys = keys;
    if (matrix && (rotation || translation)) {
      Fail(source, LineOf(*matrix), "the " + std::string(role) + " poses are given twice: " + keys,
           "keep one of them");
    }
    if (matrix) {
      const YAML::Node& items = RequireList(*matrix, source, spelling.matrix);
      for (size_t i = 0; i < items.size(); ++i) {
        const std::string what = std::string(spelling.matrix) + "[" + std::to_string(i) + "]";
        list.poses.push_back(
            ReadHomogeneous(items[i], metres_per_unit, source, what, &rotation_input));
        list.lines.push_back(LineOf(items[i]));
      }
      continue;
    }
    if (!rotation || !translation) {
      Fail(source, LineOf(rotation ? *rotation : *translation),
           std::string(rotation ? spelling.rotation : spelling.translation) + " has no matching " +
               (rotation ? spelling.translation : spelling.rotation),
           "give rotations and translations together");
    }
    const YAML::Node& rotations = RequireList(*rotation, source, spelling.rotation);
    const YAML::Node& translations = RequireList(*translation, source, spelling.translation);
    if (rotations.size() != translations.size()) {
      Fail(source, LineOf(translations),
           std::string(spelling.rotation) + " has " + std::to_string(rotations.size()) +
               " entries but " + spelling.translation + " has " +
               std::to_string(translations.size()),
           "give one translation per rotation");
    }
    for (size_t i = 0; i < rotations.size(); ++i) {
      const std::string what = std::string(role) + " pose " + std::to_string(i) + " (" +
                               spelling.rotation + "[" + std::to_string(i) + "])";
      list.poses.push_back(ReadRotationAndTranslation(
          rotations[i], translations[i], metres_per_unit, source, what, &rotation_input));
      list.lines.push_back(LineOf(rotations[i]));
    }
  }
  if (list.spelling == nullptr) {
    Fail(source, 0,
         std::string("no ") + role + " poses (" + spellings[0].rotation + "/" +
             spellings[0].translation + " or " + spellings[0].matrix + ")",
         kLayoutFix);
  }
  if (list.spelling->inverse) {
    for (Pose& pose : list.poses) pose = pose.inverse();
  }
  list.notes = rotation_input.Notes();
  return list;
}

ImportedPoses ParseOpenCvYaml(std::string_view yaml_text, const std::string& source,
                              LengthUnit unit) {
  const YAML::Node root = import_internal::LoadYaml(yaml_text, source);
  if (!root.IsMap()) Fail(source, 0, "the file is not a YAML map", kLayoutFix);
  const double metres_per_unit = MetresPer(unit);
  const PoseList robot = ReadPoseList(root, kRobotSpellings, metres_per_unit, source, "robot");
  const PoseList camera = ReadPoseList(root, kCameraSpellings, metres_per_unit, source, "camera");
  if (robot.poses.size() != camera.poses.size()) {
    Fail(source, 0,
         "there are " + std::to_string(robot.poses.size()) + " robot poses (" + robot.keys +
             ") but " + std::to_string(camera.poses.size()) + " camera poses (" + camera.keys + ")",
         "give one camera pose per robot pose");
  }
  if (robot.poses.empty()) Fail(source, 0, "the pose lists are empty", kLayoutFix);

  std::vector<std::string> ids;
  if (const std::optional<YAML::Node> id_node = Find(root, "ids")) {
    const YAML::Node& items = RequireList(*id_node, source, "ids");
    if (items.size() != robot.poses.size()) {
      Fail(source, LineOf(items),
           "ids has " + std::to_string(items.size()) + " entries for " +
               std::to_string(robot.poses.size()) + " poses",
           "give one id per pose");
    }
    std::set<std::string> seen;
    for (size_t i = 0; i < items.size(); ++i) {
      std::string id =
          import_internal::ScalarText(items[i], source, "ids[" + std::to_string(i) + "]");
      if (id.empty() || id.find_first_of("\r\n") != std::string::npos) {
        Fail(source, LineOf(items[i]),
             "ids[" + std::to_string(i) +
                 "] is empty or has a line "
                 "break",
             "give every pose a one-line name");
      }
      if (!seen.insert(id).second) {
        Fail(source, LineOf(items[i]), "id " + import_internal::Quoted(id) + " repeats",
             "give every pose its own id");
      }
      ids.push_back(std::move(id));
    }
  }

  ImportedPoses result;
  result.robot = import_internal::MakeTable(source, unit);
  result.camera = import_internal::MakeTable(source, unit);
  for (size_t i = 0; i < robot.poses.size(); ++i) {
    const std::string id = ids.empty() ? std::to_string(i) : ids[i];
    PoseRow robot_row;
    robot_row.pose = robot.poses[i];
    robot_row.id = id;
    robot_row.line = robot.lines[i];
    PoseRow camera_row;
    camera_row.pose = camera.poses[i];
    camera_row.id = id;
    camera_row.line = camera.lines[i];
    result.robot.rows.push_back(std::move(robot_row));
    result.camera->rows.push_back(std::move(camera_row));
  }
  result.robot.warnings = robot.notes;
  result.camera->warnings = camera.notes;
  const std::string format = "format: opencv-yaml (cv::calibrateHandEye arrays, FileStorage YAML)";
  const std::string units = import_internal::UnitNote(unit, "from --units; the file does not say");
  const std::string id_note = ids.empty() ? "id: 0-based pose index" : "id: the file's ids list";
  result.robot_notes = {format,
                        "source: " + source,
                        import_internal::RobotFrameNote(),
                        "convention: " + robot.keys + ": " + robot.spelling->meaning,
                        units,
                        id_note};
  result.camera_notes = {format,
                         "source: " + source,
                         import_internal::CameraFrameNote(),
                         "convention: " + camera.keys + ": " + camera.spelling->meaning,
                         units,
                         id_note};
  return result;
}

}  // namespace

ImportedPoses ParseOpenCvHandEyeYaml(std::string_view yaml_text, const std::string& source,
                                     LengthUnit unit) {
  return import_internal::GuardYaml(source,
                                    [&] { return ParseOpenCvYaml(yaml_text, source, unit); });
}

}  // namespace hecal::io
