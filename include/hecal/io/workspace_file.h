// workspace.yaml for `hecal plan` (docs/plan.md#the-workspace-file): where the robot may put its
// flange, and the nominal scene the plan is made for.
//
//   units: mm                        # lengths of this file: m (default) or mm
//   position_min: [300, -300, 150]   # the flange's position box in the robot base frame
//   position_max: [800, 300, 700]
//   tilt_axis: [0, 0, -1]            # the cone of the flange's z axis (base frame; default down)
//   max_tilt_deg: 60                 #   and its half-angle (default 60)
//   hand_eye: [x, y, z, qw, qx, qy, qz]   # nominal X: T_gripper_camera eye-in-hand,
//                                          #   T_base_camera eye-to-hand
//   target: [x, y, z, qw, qx, qy, qz]     # nominal Z: T_base_target eye-in-hand,
//                                          #   T_gripper_target eye-to-hand
//   nominal_error: [5, 20]           # how far the nominals may be off: degrees, file length unit
//                                    #   (default 5°, 20 mm); the plan is made robust to it
// position_min and position_max are required; hand_eye and target are required for a new plan
// (`hecal plan --existing` takes them from the existing calibration). Errors are
// hecal::InputError with the file, the key's line, what is wrong and how to fix it.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "hecal/geometry/types.h"

namespace hecal::io {

struct Workspace {
  Eigen::Vector3d position_min = Eigen::Vector3d::Zero();  // metres, base frame
  Eigen::Vector3d position_max = Eigen::Vector3d::Zero();
  Eigen::Vector3d tilt_axis = -Eigen::Vector3d::UnitZ();  // unit
  double max_tilt = 1.0471975511965976;                  // radians (60°)
  std::optional<Pose> hand_eye;  // nominal X (absent: the plan needs another source of it)
  std::optional<Pose> target;    // nominal Z
  double nominal_rotation_error = 0.08726646259971647;    // radians (5°)
  double nominal_translation_error = 0.02;                // metres

  // True when a flange pose T_base_gripper is inside the box and the cone.
  bool Contains(const Pose& T_base_gripper) const;
};

Workspace ReadWorkspaceFile(const std::string& path);
Workspace ParseWorkspaceYaml(std::string_view text, const std::string& source);

}  // namespace hecal::io
