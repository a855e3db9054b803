// `hecal import`: other tools' calibration-sample files → hecal's canonical robot/camera pose
// tables (docs/conventions.md). One reader per format, each in its own header (conventions there
// and in docs/import-formats.md):
//
//   format        INPUT...                              conventions applied
//   moveit        pose_samples.json                     none (T_base_eef, T_camera_target), m
//   easy_handeye  NAME.samples (YAML)                   robot inverted for eye_on_base, m
//   camodocal     TransformPairsInput.yml               none (T1 = T_base_ee, T2 = T_camera_tag), m
//   ethz          ROBOT.csv CAMERA.csv (two streams)    camera inverted (T_W_E → T_E_W), m, stamps
//   tabb          robot_cali.txt cali.txt | DIR         robot inverted (B_i = T_gripper_base), mm
//   opencv-yaml   FILE.yml (calibrateHandEye arrays)    by key name (…2gripper / cam2… inverted)
//   matrix16      ROBOT.txt [CAMERA.txt]                none (T_base_gripper, T_camera_target)
//   visp          DIRs | pose_*_<i>.yaml files, globs   none (rPe/fPe = rMe, cPo = cMo), m
//
// --robot-inverse / --camera-inverse apply to every format: the file holds the inverse of what
// the format documents, so after the format's own convention every pose of that side is
// inverted once more (and a header line says so).
//
// ImportFiles reads the files and runs the reader. Rotations follow the rule every pose reader
// shares (rotation_input.h): nearly orthonormal matrices are projected onto SO(3) and nearly unit
// quaternions normalised, with a note in the table's warnings beyond 1e-6. Every reader rejects
// bad input with hecal::InputError (file, line where known, what, how to fix): unreadable files,
// syntax errors, NaN/Inf, matrices that are not rotations beyond the tolerance (1e-3, or the
// printed precision up to 1e-2; the message says why: a reflection, a scale, too few digits, not
// orthonormal), zero or non-unit quaternions, counts that disagree with the file's own
// N / frameCount, and robot and camera counts that differ (except ethz, whose streams are
// unsynchronised).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hecal/io/import_types.h"
#include "hecal/io/units.h"

namespace hecal::io {

enum class ImportFormat {
  kMoveit,
  kEasyHandeye,
  kCamodocal,
  kEthz,
  kTabb,
  kOpenCvYaml,
  kMatrix16,
  kVisp
};

// "moveit" | "easy_handeye" | "camodocal" | "ethz" | "tabb" | "opencv-yaml" | "matrix16" | "visp".
std::optional<ImportFormat> ParseImportFormat(std::string_view text);
std::string_view ImportFormatName(ImportFormat format);
// "moveit|easy_handeye|camodocal|ethz|tabb|opencv-yaml|matrix16|visp", for help and messages.
std::string ImportFormatList();

struct ImportOptions {
  // --units: the length unit of formats whose files do not fix it (matrix16, opencv-yaml).
  std::optional<LengthUnit> units;
  // --setup: easy_handeye files that do not say eye_in_hand / eye_on_base.
  std::optional<ImportSetup> setup;
  // --robot-inverse / --camera-inverse, any format: the robot (camera) file holds the inverse of
  // what the format documents; every robot (camera) pose is inverted after the format's own
  // convention. --camera-inverse needs a camera side (not a robot-only matrix16 import).
  bool robot_inverse = false;
  bool camera_inverse = false;

  // core/options_check.h, for `format` (the options that apply depend on it): false naming
  // ImportOptions.units (given for a format whose files fix their unit) or .setup (given for a
  // format other than easy_handeye). --camera-inverse without a camera file is known only from
  // the inputs; ImportFiles refuses it.
  bool IsValid(ImportFormat format, std::string* why) const;
};

// Reads `inputs` (paths; see the table above for how many) in `format`. Options that do not apply
// to the format are rejected (InputError naming the flag), so a flag is never silently ignored.
// For tabb, `inputs` is either the two files (robot_cali.txt first) or one directory holding
// robot_cali.txt and cali.txt. For visp, any number of directories, files and glob patterns
// (ListVispPoseFiles in import_visp.h).
ImportedPoses ImportFiles(ImportFormat format, const std::vector<std::string>& inputs,
                          const ImportOptions& options);

}  // namespace hecal::io
