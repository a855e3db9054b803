// OpenCV hand–eye arrays in FileStorage YAML → robot and camera pose tables.
//
// hecal's definition of the `opencv-yaml` format: the inputs of cv::calibrateHandEye, written by
// cv::FileStorage (`fs << "R_gripper2base" << std::vector<cv::Mat>{...}`), one list per name:
//   %YAML:1.0
//   ---
//   R_gripper2base:   # N rotations: 3×3 matrices, or 3×1 rotation vectors (Rodrigues, radians)
//      - !!opencv-matrix {rows: 3, cols: 3, dt: d, data: [r11, r12, ..., r33]}
//   t_gripper2base:   # N translations, 3×1
//   R_target2cam:     # N rotations, as above
//   t_target2cam:     # N translations
//   ids: [...]        # optional: N names (e.g. image stems); else ids are 0, 1, ...
// Variants accepted:
//   - T_gripper2base / T_target2cam: N homogeneous 4×4 (or 3×4) matrices instead of R_/t_ lists;
//   - the inverse directions R_base2gripper / t_base2gripper / T_base2gripper (the pose of the
//     base in the gripper frame) and R_cam2target / t_cam2target / T_cam2target: hecal inverts
//     them; world2cam / cam2world (calibrateRobotWorldHandEye's names) mean target2cam /
//     cam2target;
//   - each matrix as an !!opencv-matrix, a flat YAML list, or a list of row lists.
// gripper2base = T_base_gripper and target2cam = T_camera_target (OpenCV's documentation of
// calibrateHandEye), so those are used as they are. Lengths: the file does not say; `unit` (the
// --units flag, default metres) gives them, and the CSV is written in that unit.
#pragma once

#include <string>
#include <string_view>

#include "hecal/io/import_types.h"
#include "hecal/io/units.h"

namespace hecal::io {

ImportedPoses ParseOpenCvHandEyeYaml(std::string_view yaml_text, const std::string& source,
                                     LengthUnit unit);

}  // namespace hecal::io
