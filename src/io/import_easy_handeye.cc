#include "hecal/io/import_easy_handeye.h"

#include <algorithm>
#include <cmath>

#include "import_internal.h"
#include "import_yaml.h"

namespace hecal::io {
namespace {

using import_internal::Fail;
using import_internal::Find;
using import_internal::LineOf;
using import_internal::Origin;

constexpr const char* kFormatFix =
    "give an easy_handeye samples file (samples: [{robot: {translation, rotation}, tracking: "
    "{translation, rotation}}, ...])";

struct Transform {
  Pose pose;
  std::optional<double> stamp;
  int line = 0;
};

std::optional<double> ReadStamp(const YAML::Node& header, const std::string& source,
                                const std::string& what) {
  const std::optional<YAML::Node> stamp = Find(header, "stamp");
  if (!stamp) return std::nullopt;
  // ROS 2 builtin_interfaces/Time {sec, nanosec}; ROS 1 {secs, nsecs}.
  const std::optional<YAML::Node> seconds =
      Find(*stamp, "sec") ? Find(*stamp, "sec") : Find(*stamp, "secs");
  const std::optional<YAML::Node> nanoseconds =
      Find(*stamp, "nanosec") ? Find(*stamp, "nanosec") : Find(*stamp, "nsecs");
  if (!seconds) return std::nullopt;
  double value = import_internal::ScalarNumber(*seconds, source, what + " stamp sec").value;
  if (nanoseconds) {
    value +=
        1e-9 * import_internal::ScalarNumber(*nanoseconds, source, what + " stamp nanosec").value;
  }
  if (!std::isfinite(value)) {
    Fail(source, LineOf(*stamp), what + " has a non-finite stamp", "write a finite time stamp");
  }
  return value;
}

// geometry_msgs/Transform {translation: {x, y, z}, rotation: {x, y, z, w}}, or a TransformStamped
// {header: {stamp}, transform: {...}}.
Transform ReadTransform(const YAML::Node& node, const std::string& source, const std::string& what,
                        RotationInput* rotations) {
  Transform result;
  result.line = LineOf(node);
  // (Never assign one YAML::Node to another: yaml-cpp's operator= rewrites the referenced node.)
  const std::optional<YAML::Node> inner = Find(node, "transform");
  const YAML::Node body = inner ? *inner : node;
  if (inner) {
    if (const std::optional<YAML::Node> header = Find(node, "header")) {
      result.stamp = ReadStamp(*header, source, what);
    }
  }
  const std::optional<YAML::Node> translation = Find(body, "translation");
  const std::optional<YAML::Node> rotation = Find(body, "rotation");
  if (!translation || !rotation) {
    Fail(source, LineOf(body),
         what + " is not a transform with translation {x, y, z} and rotation {x, y, z, w}",
         kFormatFix);
  }
  Eigen::Vector3d t;
  const char* axes[3] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) {
    const std::optional<YAML::Node> value = Find(*translation, axes[k]);
    if (!value) {
      Fail(source, LineOf(*translation), what + " translation has no " + axes[k],
           "write translation: {x, y, z}");
    }
    t[k] = import_internal::ScalarNumber(*value, source, what + " translation " + axes[k]).value;
  }
  Eigen::Vector4d wxyz;
  double rounding = 0.0;
  const char* components[4] = {"w", "x", "y", "z"};
  for (int k = 0; k < 4; ++k) {
    const std::optional<YAML::Node> value = Find(*rotation, components[k]);
    if (!value) {
      Fail(source, LineOf(*rotation), what + " rotation has no " + components[k],
           "write rotation: {x, y, z, w} (a unit quaternion)");
    }
    const import_internal::Number number =
        import_internal::ScalarNumber(*value, source, what + " rotation " + components[k]);
    wxyz[k] = number.value;
    rounding = std::max(rounding, number.rounding);
  }
  result.pose =
      import_internal::PoseFromQuaternion(t, wxyz, rounding, 1.0, Origin{source, result.line, what},
                                          "rotation {x, y, z, w}", rotations);
  return result;
}

struct Parameters {
  std::optional<ImportSetup> setup;
  int setup_line = 0;
  std::string robot_base_frame = "robot_base_frame";
  std::string robot_effector_frame = "robot_effector_frame";
  std::string tracking_base_frame = "tracking_base_frame";
  std::string tracking_marker_frame = "tracking_marker_frame";
};

Parameters ReadParameters(const YAML::Node& root, const std::string& source) {
  Parameters parameters;
  const std::optional<YAML::Node> node = Find(root, "parameters");
  if (!node) return parameters;
  if (const std::optional<YAML::Node> type = Find(*node, "calibration_type")) {
    const std::string text =
        type->IsNull() ? "" : import_internal::ScalarText(*type, source, "calibration_type");
    parameters.setup_line = LineOf(*type);
    if (text == "eye_in_hand") {
      parameters.setup = ImportSetup::kEyeInHand;
    } else if (text == "eye_on_base") {
      parameters.setup = ImportSetup::kEyeToHand;
    } else if (!text.empty()) {
      Fail(source, LineOf(*type),
           "calibration_type is " + import_internal::Quoted(text) +
               ", not eye_in_hand or eye_on_base",
           "set calibration_type to eye_in_hand or eye_on_base");
    }
  }
  if (const std::optional<YAML::Node> eye_on_hand = Find(*node, "eye_on_hand")) {
    if (!eye_on_hand->IsNull()) {
      const std::string text = import_internal::ScalarText(*eye_on_hand, source, "eye_on_hand");
      bool value = false;
      if (!YAML::convert<bool>::decode(*eye_on_hand, value)) {
        Fail(source, LineOf(*eye_on_hand),
             "eye_on_hand is " + import_internal::Quoted(text) + ", not true or false",
             "write eye_on_hand: true or false");
      }
      const ImportSetup setup = value ? ImportSetup::kEyeInHand : ImportSetup::kEyeToHand;
      if (parameters.setup && *parameters.setup != setup) {
        Fail(source, LineOf(*eye_on_hand), "eye_on_hand contradicts calibration_type",
             "keep one of them, or make them agree");
      }
      parameters.setup = setup;
      parameters.setup_line = LineOf(*eye_on_hand);
    }
  }
  const auto frame = [&](const char* key, std::string* out) {
    if (const std::optional<YAML::Node> value = Find(*node, key)) {
      if (value->IsScalar() && !value->Scalar().empty()) *out = value->Scalar();
    }
  };
  frame("robot_base_frame", &parameters.robot_base_frame);
  frame("robot_effector_frame", &parameters.robot_effector_frame);
  frame("tracking_base_frame", &parameters.tracking_base_frame);
  frame("tracking_marker_frame", &parameters.tracking_marker_frame);
  return parameters;
}

std::string_view SetupText(ImportSetup setup) {
  return setup == ImportSetup::kEyeInHand ? "eye_in_hand" : "eye_on_base";
}

ImportedPoses ParseEasyHandeyeYaml(std::string_view yaml_text, const std::string& source,
                                   std::optional<ImportSetup> setup_flag) {
  const YAML::Node root = import_internal::LoadYaml(yaml_text, source);
  if (!root.IsMap()) Fail(source, 0, "the file is not a YAML map", kFormatFix);

  // The samples: one list of {robot, tracking|optical}, or two lists (ROS 1 SampleList).
  std::vector<std::pair<YAML::Node, YAML::Node>> samples;
  const std::optional<YAML::Node> list = Find(root, "samples");
  const std::optional<YAML::Node> hand_world = Find(root, "hand_world_samples");
  const std::optional<YAML::Node> camera_marker = Find(root, "camera_marker_samples");
  if (list) {
    const YAML::Node& items = *list;
    if (!items.IsSequence()) Fail(source, LineOf(items), "samples is not a list", kFormatFix);
    for (size_t i = 0; i < items.size(); ++i) {
      const YAML::Node sample = items[i];
      const std::string name = "sample " + std::to_string(i);
      const std::optional<YAML::Node> robot = Find(sample, "robot");
      const std::optional<YAML::Node> tracking =
          Find(sample, "tracking") ? Find(sample, "tracking") : Find(sample, "optical");
      if (!robot || !tracking) {
        Fail(source, LineOf(sample), name + " lacks " + (robot ? "tracking" : "robot"),
             "give every sample a robot and a tracking transform");
      }
      samples.emplace_back(*robot, *tracking);
    }
  } else if (hand_world || camera_marker) {
    if (!hand_world || !camera_marker || !hand_world->IsSequence() ||
        !camera_marker->IsSequence()) {
      Fail(source, LineOf(hand_world ? *hand_world : *camera_marker),
           "hand_world_samples and camera_marker_samples must both be lists", kFormatFix);
    }
    if (hand_world->size() != camera_marker->size()) {
      Fail(source, LineOf(*camera_marker),
           "hand_world_samples has " + std::to_string(hand_world->size()) +
               " transforms but camera_marker_samples has " + std::to_string(camera_marker->size()),
           "give one camera_marker sample per hand_world sample");
    }
    const YAML::Node& robots = *hand_world;
    const YAML::Node& cameras = *camera_marker;
    for (size_t i = 0; i < robots.size(); ++i) samples.emplace_back(robots[i], cameras[i]);
  } else if (Find(root, "transformation") || Find(root, "transform")) {
    Fail(source, 0, "this is an easy_handeye calibration result, not a list of samples",
         "import the samples file (easy_handeye2 saves it as NAME.samples next to NAME.calib)");
  } else {
    Fail(source, 0, "no samples in the file", kFormatFix);
  }
  if (samples.empty()) Fail(source, 0, "the sample list is empty", "take at least one sample");

  const Parameters parameters = ReadParameters(root, source);
  if (setup_flag && parameters.setup && *setup_flag != *parameters.setup) {
    Fail("ImportOptions.setup", 0,
         "contradicts " + source + ":" + std::to_string(parameters.setup_line) + ", which says " +
             std::string(SetupText(*parameters.setup)),
         "leave the setup unset or fix the file");
  }
  const std::optional<ImportSetup> setup = parameters.setup ? parameters.setup : setup_flag;
  if (!setup) {
    Fail(source, 0,
         "the file does not say whether it is eye_in_hand or eye_on_base (parameters."
         "calibration_type is empty or missing), and easy_handeye stores the robot transform "
         "inverted for eye_on_base",
         "pass --setup eye-in-hand or --setup eye-to-hand");
  }

  ImportedPoses result;
  result.robot = import_internal::MakeTable(source, LengthUnit::kMetre);
  result.camera = import_internal::MakeTable(source, LengthUnit::kMetre);
  std::vector<std::optional<double>> robot_stamps;
  std::vector<std::optional<double>> camera_stamps;
  RotationInput robot_rotations(source, "robot");
  RotationInput camera_rotations(source, "tracking");
  for (size_t i = 0; i < samples.size(); ++i) {
    const std::string name = "sample " + std::to_string(i);
    const Transform robot =
        ReadTransform(samples[i].first, source, name + " robot", &robot_rotations);
    const Transform camera =
        ReadTransform(samples[i].second, source, name + " tracking", &camera_rotations);
    PoseRow robot_row;
    robot_row.pose = *setup == ImportSetup::kEyeInHand ? robot.pose : robot.pose.inverse();
    robot_row.id = std::to_string(i);
    robot_row.line = robot.line;
    PoseRow camera_row;
    camera_row.pose = camera.pose;
    camera_row.id = std::to_string(i);
    camera_row.line = camera.line;
    robot_stamps.push_back(robot.stamp);
    camera_stamps.push_back(camera.stamp);
    result.robot.rows.push_back(std::move(robot_row));
    result.camera->rows.push_back(std::move(camera_row));
  }
  // Stamps only when every transform of a table has one (a column is all or nothing).
  const auto set_stamps = [](const std::vector<std::optional<double>>& stamps, PoseTable* table) {
    for (const std::optional<double>& stamp : stamps) {
      if (!stamp) return;
    }
    for (size_t i = 0; i < stamps.size(); ++i) table->rows[i].stamp = stamps[i];
  };
  set_stamps(robot_stamps, &result.robot);
  set_stamps(camera_stamps, &*result.camera);
  result.robot.warnings = robot_rotations.Notes();
  result.camera->warnings = camera_rotations.Notes();

  const std::string setup_source = parameters.setup ? "from the file" : "from --setup";
  const std::string format = "format: easy_handeye (samples YAML), " +
                             std::string(SetupText(*setup)) + " (" + setup_source + ")";
  const std::string& base = parameters.robot_base_frame;
  const std::string& effector = parameters.robot_effector_frame;
  const std::string robot_convention =
      *setup == ImportSetup::kEyeInHand
          ? "convention: robot = lookup_transform(" + base + ", " + effector +
                ") = T_base_effector, used as is (no inverse)"
          : "convention: robot = lookup_transform(" + effector + ", " + base +
                ") = T_effector_base (eye_on_base), INVERTED to T_base_effector";
  result.robot_notes = {format,
                        "source: " + source,
                        import_internal::RobotFrameNote(),
                        robot_convention,
                        import_internal::UnitNote(LengthUnit::kMetre, "ROS transforms"),
                        "id: 0-based sample index"};
  result.camera_notes = {
      format,
      "source: " + source,
      import_internal::CameraFrameNote(),
      "convention: tracking = lookup_transform(" + parameters.tracking_base_frame + ", " +
          parameters.tracking_marker_frame + ") = T_camera_marker, used as is (no inverse)",
      import_internal::UnitNote(LengthUnit::kMetre, "ROS transforms"),
      "id: 0-based sample index"};
  return result;
}

}  // namespace

ImportedPoses ParseEasyHandeyeSamples(std::string_view yaml_text, const std::string& source,
                                      std::optional<ImportSetup> setup) {
  return import_internal::GuardYaml(source,
                                    [&] { return ParseEasyHandeyeYaml(yaml_text, source, setup); });
}

}  // namespace hecal::io
