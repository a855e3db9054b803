// workspace.yaml (workspace_file.h).
#include "hecal/io/workspace_file.h"

#include <array>
#include <cmath>
#include <numbers>
#include <optional>

#include "hecal/geometry/rotation.h"
#include "hecal/io/atomic_file.h"
#include "hecal/io/units.h"
#include "import_yaml.h"
#include "yaml_map.h"

namespace hecal::io {
namespace {

using import_internal::Fail;

constexpr std::array<std::string_view, 8> kKeys = {"units",     "position_min", "position_max",
                                                   "tilt_axis", "max_tilt_deg", "hand_eye",
                                                   "target",    "nominal_error"};

// A list of `count` finite numbers at `key`.
std::vector<double> Numbers(const internal::YamlMap& map, const std::string& key, size_t count,
                            const std::string& source, const std::string& example) {
  const YAML::Node node = *map.Find(key);
  const std::string fix = "write e.g. " + key + ": " + example;
  if (!node.IsSequence() || node.size() != count) {
    Fail(source, map.Line(key), key + " must be a list of " + std::to_string(count) + " numbers",
         fix);
  }
  std::vector<double> values;
  for (const YAML::Node& item : node) {
    const double value = import_internal::ScalarNumber(item, source, key).value;
    if (!std::isfinite(value))
      Fail(source, map.Line(key), key + " has a number that is not finite", fix);
    values.push_back(value);
  }
  return values;
}

const YAML::Node& Required(const internal::YamlMap& map, const std::string& key,
                           const std::string& source, const std::string& example) {
  if (!map.Has(key)) {
    Fail(source, 0, "the workspace has no '" + key + "'", "add a line " + key + ": " + example);
  }
  return map.nodes.at(key);
}

Pose PoseAt(const internal::YamlMap& map, const std::string& key, double metres,
            const std::string& source, const std::string& example) {
  const std::vector<double> v = Numbers(map, key, 7, source, example);
  const Eigen::Quaterniond q(v[3], v[4], v[5], v[6]);
  if (std::abs(q.norm() - 1.0) > 1e-3) {
    Fail(source, map.Line(key),
         key + "'s quaternion (qw, qx, qy, qz) has norm " + std::to_string(q.norm()) + ", not 1",
         "write x, y, z then a unit quaternion qw, qx, qy, qz");
  }
  return MakePose(q.normalized().toRotationMatrix(), metres * Eigen::Vector3d(v[0], v[1], v[2]));
}

Workspace ParseWorkspace(const YAML::Node& root, const std::string& source) {
  if (!root.IsMap()) {
    Fail(source, import_internal::LineOf(root),
         "the workspace file is not a map of 'key: value' lines",
         "write one 'key: value' per line (see docs/plan.md)");
  }
  const internal::YamlMap map = internal::ReadYamlMap(root, source);
  internal::RejectUnknownKeys(map, kKeys, source, "");
  double metres = 1.0;
  if (map.Has("units")) {
    const std::string text = import_internal::ScalarText(*map.Find("units"), source, "units");
    const std::optional<LengthUnit> unit = ParseLengthUnit(text);
    if (!unit)
      Fail(source, map.Line("units"), "unknown unit '" + text + "'", "write units: m or units: mm");
    metres = MetresPer(*unit);
  }
  Workspace workspace;
  Required(map, "position_min", source, "[0.3, -0.3, 0.15]");
  Required(map, "position_max", source, "[0.8, 0.3, 0.7]");
  const std::vector<double> low = Numbers(map, "position_min", 3, source, "[0.3, -0.3, 0.15]");
  const std::vector<double> high = Numbers(map, "position_max", 3, source, "[0.8, 0.3, 0.7]");
  for (int k = 0; k < 3; ++k) {
    workspace.position_min(k) = metres * low[k];
    workspace.position_max(k) = metres * high[k];
    if (!(workspace.position_min(k) < workspace.position_max(k))) {
      Fail(source, map.Line("position_max"),
           "position_max is not above position_min along " + std::string(1, "xyz"[k]),
           "give the box's lower corner in position_min and its upper corner in position_max");
    }
  }
  if (map.Has("tilt_axis")) {
    const std::vector<double> a = Numbers(map, "tilt_axis", 3, source, "[0, 0, -1]");
    const Eigen::Vector3d axis(a[0], a[1], a[2]);
    if (!(axis.norm() > 0.0))
      Fail(source, map.Line("tilt_axis"), "tilt_axis is zero", "write e.g. tilt_axis: [0, 0, -1]");
    workspace.tilt_axis = axis.normalized();
  }
  if (map.Has("max_tilt_deg")) {
    const double tilt =
        import_internal::ScalarNumber(*map.Find("max_tilt_deg"), source, "max_tilt_deg").value;
    if (!(tilt > 0.0 && tilt <= 180.0)) {
      Fail(source, map.Line("max_tilt_deg"), "max_tilt_deg must be in (0, 180]",
           "write e.g. max_tilt_deg: 60");
    }
    workspace.max_tilt = tilt * std::numbers::pi / 180.0;
  }
  if (map.Has("hand_eye"))
    workspace.hand_eye = PoseAt(map, "hand_eye", metres, source, "[0.03, 0.0, 0.08, 1, 0, 0, 0]");
  if (map.Has("target"))
    workspace.target = PoseAt(map, "target", metres, source, "[0.5, 0.0, 0.0, 0, 1, 0, 0]");
  if (map.Has("nominal_error")) {
    const std::vector<double> e = Numbers(map, "nominal_error", 2, source, "[5, 20]");
    if (!(e[0] >= 0.0 && e[1] >= 0.0)) {
      Fail(source, map.Line("nominal_error"), "nominal_error must not be negative",
           "write degrees and a length, e.g. nominal_error: [5, 20] (with units: mm)");
    }
    workspace.nominal_rotation_error = e[0] * std::numbers::pi / 180.0;
    workspace.nominal_translation_error = e[1] * metres;
  }
  return workspace;
}

}  // namespace

bool Workspace::Contains(const Pose& T_base_gripper) const {
  const Eigen::Vector3d p = T_base_gripper.translation();
  if ((p.array() < position_min.array()).any() || (p.array() > position_max.array()).any())
    return false;
  const double cosine = T_base_gripper.linear().col(2).dot(tilt_axis);
  return cosine >= std::cos(max_tilt) - 1e-12;
}

Workspace ParseWorkspaceYaml(std::string_view text, const std::string& source) {
  return import_internal::GuardYaml(
      source, [&] { return ParseWorkspace(import_internal::LoadYaml(text, source), source); });
}

Workspace ReadWorkspaceFile(const std::string& path) {
  return ParseWorkspaceYaml(ReadFile(path), path);
}

}  // namespace hecal::io
