// Calibration from two pose tables as one job (`hecal calibrate --camera FILE`; docs/architecture.md,
// "The data flow of hecal calibrate", from poses): everything between the caller's options and
// the result document, printing nothing.
//
// Steps (CalibrateFromPoseFiles)
//   1. The options checked (IsValid) before any file is read.
//   2. The robot table (T_base_gripper) and the camera table (T_camera_target) read
//      (io/pose_table.h), each with its own read options (units, angles, Euler sequence, and
//      whether to invert every pose on reading), and the stations paired by id or by order
//      (io::PairStations).
//   3. The same poses given twice refused: one file given as both (or a copy of it), or a camera
//      table that holds the robot's poses or their inverses (to 1e-12). Such data fit every X.
//   4. The convention check (handeye/convention_check.h) in the caller's words (options.words):
//      it stops with the fix for a mistake that fits clearly better (the other setup, an
//      inverted file, millimetres read as metres, quaternion columns one place off), or picks the
//      setup when options.setup is empty; its notes and then each table's warnings become the
//      document's first warnings.
//   5. CalibratePairedPoses (pose_calibration.h), which runs steps 3 (the same poses in both
//      tables) and 4 in its own terms, then the method of options.calibrate,
//      or every method of estimation::AllMethods() when options.all_methods, with covariance,
//      outlier rejection and the plausibility checks.
// Frames and units: X and Z as handeye/problem.h defines them for the setup; lengths in the
// robot table's unit (it labels the document), angles in radians (docs/conventions.md).
//
// Errors (hecal::InputError): invalid options (source the field: CalibrateOptions.*,
// PoseReadOptions.*, PoseFileCalibrationOptions.robot / .camera); the same poses given twice
// (source the camera file; the texts name the two tables by options.file_words); those of the
// tables, the pairing, the convention check and the calibration (also DegenerateError) pass
// through. Nothing is written.
#pragma once

#include <optional>
#include <string>

#include "hecal/estimation/calibrate.h"
#include "hecal/handeye/convention_check.h"
#include "hecal/io/pose_table.h"
#include "hecal/jobs/pose_calibration.h"
#include "hecal/report/result_file.h"

namespace hecal::jobs {

// The caller's names for the two tables in the refusal of step 3 ("is the same file as " +
// robot + " robot.csv"; "give the robot poses (...) with " + robot + " and the camera poses
// (...) with " + camera); a command line passes its flags.
struct PoseFileWords {
  std::string robot = "the robot table";
  std::string camera = "the camera table";
};

struct PoseFileCalibrationOptions {
  std::string robot;               // the robot pose table: T_base_gripper, one row per station
  std::string camera;              // the camera pose table: T_camera_target, one row per station
  io::PoseReadOptions robot_read;  // its units, angles, Euler sequence; invert on reading
  io::PoseReadOptions camera_read;
  std::optional<handeye::Setup> setup;  // nullopt: the convention check picks it
  // Method, noise, robust loss, covariance, outlier rejection (the method is ignored when
  // all_methods).
  estimation::CalibrateOptions calibrate;
  bool all_methods = false;        // every method of estimation::AllMethods(), compared
  handeye::ConventionWords words;  // the convention check's texts in the caller's words
  PoseFileWords file_words;        // the tables' names in the refusal of step 3

  // core/options_check.h: false naming the first bad field, in the order calibrate
  // (CalibrateOptions::IsValid), PoseFileCalibrationOptions.robot and .camera (empty),
  // robot_read and camera_read (PoseReadOptions::IsValid).
  bool IsValid(std::string* why) const;
};

struct PoseFileCalibration {
  report::ResultDocument document;  // what report::WriteResult writes; one result per method
};

// Steps 4–5's input: the stations of the two tables (paired by the caller: io::PairStations here,
// by time for streams, stream_calibration.h) with what the tables and options know of them.
PairedPoses PairedTablePoses(const PoseFileCalibrationOptions& options, const io::PoseTable& robot,
                             const io::PoseTable& camera, const io::Stations& stations);

// Steps 1–5 above.
PoseFileCalibration CalibrateFromPoseFiles(const PoseFileCalibrationOptions& options);

}  // namespace hecal::jobs
