// Plain matrix files: one pose per line as 16 numbers (a row-major 4×4 homogeneous matrix,
// r11 r12 r13 tx r21 ... 0 0 0 1) or 12 numbers (row-major 3×4), separated by spaces, tabs or
// commas; blank lines and '#' comment lines are skipped. Example: RWHE-Calib's RobotPosesVec.txt
// (data/rwhe-kuka2: T_base_tcp in metres).
//
// The file does not say what it holds, so the defaults are hecal's inputs: the robot file holds
// T_base_gripper and the camera file T_camera_target, in `unit` (the --units flag, default
// metres). Files that hold the inverse (T_gripper_base / T_target_camera) are imported with
// --robot-inverse / --camera-inverse, which ImportFiles (import.h) applies to every format. The
// camera file is optional; when given, both files must have the same number of poses. Ids are
// the 0-based pose index (line k of both files is station k).
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "hecal/io/import_types.h"
#include "hecal/io/units.h"

namespace hecal::io {

struct Matrix16Options {
  LengthUnit unit = LengthUnit::kMetre;
};

// `camera_text` nullopt: robot poses only (ImportedPoses::camera stays empty).
ImportedPoses ParseMatrix16(std::string_view robot_text, const std::string& robot_source,
                            std::optional<std::string_view> camera_text,
                            const std::string& camera_source, const Matrix16Options& options);

}  // namespace hecal::io
