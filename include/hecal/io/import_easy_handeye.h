// easy_handeye / easy_handeye2 sample lists (ROS; github.com/IFL-CAMP/easy_handeye and
// github.com/marcoesposito1988/easy_handeye2) → robot and camera pose tables.
//
// Format (YAML, what easy_handeye2's "save samples" writes to ~/.ros2/easy_handeye2/
// calibrations/NAME.samples: the easy_handeye2_msgs/SampleList message as YAML):
//   parameters: {name, calibration_type: eye_in_hand | eye_on_base, robot_base_frame,
//                robot_effector_frame, tracking_base_frame, tracking_marker_frame, ...}
//   samples:
//     - robot:    {translation: {x, y, z}, rotation: {x, y, z, w}}
//       tracking: {translation: {x, y, z}, rotation: {x, y, z, w}}
// geometry_msgs/Transform: metres, Hamilton quaternion in x, y, z, w order.
// Also accepted (ROS 1 easy_handeye): `optical` for `tracking` (the sampler's dictionary key),
// the SampleList message `hand_world_samples` / `camera_marker_samples` (two lists),
// `parameters: {eye_on_hand: true|false}`, and TransformStamped entries
// ({header: {stamp: {sec, nanosec} | {secs, nsecs}}, transform: {...}}), whose stamps are kept.
//
// Conventions (handeye_sampler.py, _get_transforms; tf2 lookup_transform(target, source) returns
// the pose of `source` in `target`):
//   eye_in_hand: robot = lookup_transform(robot_base_frame, robot_effector_frame)
//                      = T_base_effector → robot row as is
//   eye_on_base: robot = lookup_transform(robot_effector_frame, robot_base_frame)
//                      = T_effector_base → INVERTED to T_base_effector
//   both:        tracking = lookup_transform(tracking_base_frame, tracking_marker_frame)
//                      = T_camera_marker → camera row as is
// So the setup must be known: from parameters.calibration_type (or eye_on_hand), else from
// `setup` (the --setup flag). A file whose calibration_type is empty and no --setup is an error,
// as is a --setup that contradicts the file. Ids are the 0-based sample index.
// A calibration *result* file (`transformation:` / `transform:` without samples) is rejected.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "hecal/io/import_types.h"

namespace hecal::io {

ImportedPoses ParseEasyHandeyeSamples(std::string_view yaml_text, const std::string& source,
                                      std::optional<ImportSetup> setup);

}  // namespace hecal::io
