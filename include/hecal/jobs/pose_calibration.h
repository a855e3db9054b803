// Calibration from paired poses (docs/architecture.md "The data flow of hecal calibrate", steps 3–8),
// the front door's job for poses already in memory (`hecal.calibrate` in Python) and the common
// tail of the pose-file job (pose_file_calibration.h).
//
// CalibratePoses (poses in memory)
//   1. The options checked (IsValid); both lists of equal length, station ids one per station,
//      every pose finite with a proper rotation (|RᵀR − I| ≤ 1e-6, det R > 0); translations
//      converted from the lists' units to metres.
//   2. CalibratePairedPoses below, with the lists' names as the sources of errors.
// CalibratePairedPoses (paired poses and what their source knows of them)
//   1. The same poses given twice refused: a camera list that holds the robot's poses or their
//      inverses (to 1e-12). Such data fit every X.
//   2. The convention check (handeye/convention_check.h): it stops with the fix for a mistake
//      that fits clearly better (the other setup, inverted poses, millimetres read as metres,
//      quaternion columns one place off), or picks the setup when none is given; its notes and
//      then the caller's notes become the document's first warnings.
//   3. CalibrateFromPoses: one selection of stations for every method
//      (estimation/station_selection.h), then estimation::Calibrate with the method of the
//      options, or with every method (`--method all`), each result's warnings preceded by the
//      notes and followed by the plausibility warnings (estimation/plausibility.h).
// The returned ResultDocument is what report::WriteResult writes (docs/result-file.md).
// Frames and units: X and Z as handeye/problem.h defines them for the setup (metres, radians
// inside); `unit` only labels the document.
//
// Errors: InputError for invalid options (source the field), lists of different lengths, a
// pose that is not finite or not a rotation (source the list's name, the index in the problem
// text), the same poses given twice, and from the convention check; with one method, its
// hecal::DegenerateError; with every method, a method that refuses the data is recorded in
// ResultDocument::failures and the others go on — when all refuse, the first refusal is thrown;
// a result that is not finite (X, Z, the residual RMS or the covariance) is a DegenerateError
// naming the likely cause (CheckFiniteResult).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "hecal/estimation/calibrate.h"
#include "hecal/estimation/plausibility.h"
#include "hecal/handeye/convention_check.h"
#include "hecal/handeye/problem.h"
#include "hecal/io/units.h"
#include "hecal/report/result_file.h"

namespace hecal::jobs {

struct PoseCalibrationOptions {
  std::optional<handeye::Setup> setup;  // nullopt: the convention check picks it
  // The unit of each list's translations; nullopt: metres, and the unit counts as not stated
  // (the convention check may then find millimetres read as metres). The document is labelled
  // in the robot list's unit.
  std::optional<io::LengthUnit> robot_unit;
  std::optional<io::LengthUnit> camera_unit;
  // Method, noise, robust loss, covariance, outlier rejection (the method is ignored when
  // all_methods).
  estimation::CalibrateOptions calibrate;
  bool all_methods = false;              // every method of estimation::AllMethods(), compared
  std::vector<std::string> station_ids;  // one per station; empty: "1", "2", ...
  std::string robot_source = "T_base_gripper";  // the lists' names in errors
  std::string camera_source = "T_camera_target";
  handeye::ConventionWords words;  // the convention check's texts in the caller's words

  // core/options_check.h: CalibrateOptions::IsValid, then PoseCalibrationOptions.robot_source
  // and .camera_source (empty).
  bool IsValid(std::string* why) const;
};

struct PoseCalibration {
  report::ResultDocument document;  // what report::WriteResult writes; one result per method
};

// CalibratePoses steps 1–2 above: T_base_gripper and T_camera_target one per station.
PoseCalibration CalibratePoses(const std::vector<Pose>& T_base_gripper,
                               const std::vector<Pose>& T_camera_target,
                               const PoseCalibrationOptions& options);

// What a source of paired poses knows of them, for CalibratePairedPoses.
struct PairedPoses {
  handeye::PoseData data;                        // the poses (metres) and what the source left open
  handeye::ConventionCheckOptions check;         // setup, sources, inversions, words
  io::LengthUnit unit = io::LengthUnit::kMetre;  // the document's unit
  std::vector<std::string> station_ids;          // one per station
  std::vector<std::string> notes;  // after the convention check's notes (e.g. a file's warnings)
  // The caller's names for the two sources in the refusal of step 1 ("holds the same poses as "
  // + robot_words + " " + check.robot_source; "give the robot poses (...) with " + robot_words).
  std::string robot_words = "the robot poses";
  std::string camera_words = "the camera poses";
};

// CalibratePairedPoses steps 1–3 above.
PoseCalibration CalibratePairedPoses(const PairedPoses& poses,
                                     const estimation::CalibrateOptions& options, bool all_methods);

struct PoseCalibrationInput {
  handeye::Problem problem;
  io::LengthUnit unit = io::LengthUnit::kMetre;  // the document's output unit
  std::vector<std::string> station_ids;          // one per station of the problem
  estimation::PlausibilityInput plausibility;
  std::vector<std::string> notes;  // put first in every result's warnings
};

// Runs the job above; `all_methods` runs every method of estimation::AllMethods().
report::ResultDocument CalibrateFromPoses(const PoseCalibrationInput& input,
                                          estimation::CalibrateOptions options, bool all_methods);

// CalibratePoses step 1 for one list: every pose finite with a proper rotation, else InputError
// naming `source` and the pose's index.
void CheckPoseList(const std::vector<Pose>& poses, const std::string& source);

// A result about to be printed and written: X, Z, the residual RMS and the covariance must be
// finite (docs/reliability.md); DegenerateError otherwise.
void CheckFiniteResult(const estimation::CalibrationResult& result);

}  // namespace hecal::jobs
