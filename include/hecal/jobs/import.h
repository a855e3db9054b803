// The import job (`hecal import`, docs/import-formats.md): another tool's calibration samples →
// the texts of hecal's canonical files, robot.csv (T_base_gripper), camera.csv (T_camera_target)
// and, for tabb, camera.yaml (the intrinsics of cali.txt). It writes nothing: the caller checks the
// output paths and writes the texts, all or none (atomic_file.h).
//
// Steps (ImportSamples)
//   1. The options checked (IsValid) before any file is read: which outputs the format can fill.
//   2. The inputs read in `format` (import.h: io::ImportFiles, with `read`'s units, setup and
//      inversions).
//   3. The texts formatted (import_output.h), their first '#' line naming hecal, its version and
//      the format.
// Frames and units: as the reader of the format documents them (import.h); lengths are written in
// the source's unit.
//
// Errors (hecal::InputError): invalid options (source the field: ImportJobOptions.robot, .camera,
// .intrinsics, or io::ImportOptions.* from io::ImportOptions::IsValid); those of the reader pass
// through; an intrinsics file asked of a tabb source whose lines hold different camera models
// (source: the camera file).
#pragma once

#include <string>
#include <vector>

#include "hecal/io/import.h"
#include "hecal/io/import_output.h"

namespace hecal::jobs {

struct ImportJobOptions {
  io::ImportFormat format = io::ImportFormat::kMoveit;
  std::vector<std::string> inputs;  // the source files (import.h: how many for each format)
  io::ImportOptions read;           // units, setup, inversions
  // The outputs the caller will write: robot.csv (required); camera.csv (required, except for a
  // robot-only matrix16 import, where it must be empty); camera.yaml ("" = none; tabb only).
  std::string robot;
  std::string camera;
  std::string intrinsics;

  // True for a matrix16 import of one file (robot poses only).
  bool RobotOnly() const;

  // core/options_check.h: false naming the first bad field, in the order robot (empty), camera
  // (empty, or given for a robot-only import), intrinsics (given for a format other than tabb),
  // then io::ImportOptions::IsValid for the format.
  bool IsValid(std::string* why) const;
};

struct ImportJob {
  io::ImportedPoses imported;  // the tables read, their sources and notes
  io::ImportTexts texts;       // what to write to robot, camera and intrinsics
  // The readers' warnings, robot's then camera's (rotations projected onto SO(3) or normalised);
  // also in the texts as '# note:' lines.
  std::vector<std::string> warnings;
};

// Steps 1–3 above.
ImportJob ImportSamples(const ImportJobOptions& options);

}  // namespace hecal::jobs
