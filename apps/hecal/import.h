// `hecal import` (docs/cli.md#hecal-import, docs/import-formats.md): another tool's calibration
// samples → the canonical pose tables, all or nothing. The readers and their conventions are
// include/hecal/io/import*.h; this command binds the flags and writes the files.
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
