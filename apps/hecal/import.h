// `hecal import` (docs/cli.md): another tool's calibration samples → the canonical pose tables
//   robot.csv   T_base_gripper_i  (id, [stamp,] x, y, z, qw, qx, qy, qz)
//   camera.csv  T_camera_target_i
// with '#' header lines naming the source file, the format, the convention applied (which poses
// were inverted) and the units, and '# note:' lines for rotations the reader projected onto SO(3)
// or normalised (io/rotation_input.h; also printed on stderr as "hecal: warning: ..."). Lengths are
// written in the source's unit (Tabb: x_mm, y_mm, z_mm). The readers and their conventions are in
// include/hecal/io/import*.h and docs/import-formats.md.
//
// All or nothing: every input is read and checked and every output formatted before the first
// file is written; each file is written atomically, and if a later one fails the earlier ones are
// restored (or removed), so a failed import leaves the output paths as they were.
#pragma once

#include <string>
#include <vector>

#include "cli.h"

namespace hecal::cli {

struct ImportCommandOptions {
  std::string format;               // moveit | easy_handeye | ... (io::ParseImportFormat)
  std::vector<std::string> inputs;  // INPUT...
  std::string robot;                // --robot robot.csv
  std::string camera;               // --camera camera.csv ("" only for robot-only matrix16)
  std::string units;                // --units m|mm (matrix16, opencv-yaml)
  std::string setup;                // --setup eye-in-hand|eye-to-hand (easy_handeye)
  bool robot_inverse = false;       // --robot-inverse (any format)
  bool camera_inverse = false;      // --camera-inverse (any format)
  std::string intrinsics;           // --intrinsics camera.yaml (tabb)
};

// Runs the import; throws hecal::InputError for bad flags or input.
void RunImport(const ImportCommandOptions& options, const Io& io);

}  // namespace hecal::cli
