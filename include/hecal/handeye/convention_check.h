// The convention check before a calibration: the poses as given are compared with the mistakes
// users make (convention_diagnosis.h: the other setup, an inverted file, millimetres read as
// metres, quaternion columns one place off). When one fits clearly better the check refuses with
// a hecal::InputError that says which, with both median station residuals ("0.78 deg / 1.3 mm",
// lengths of 1 m and more in m) and what fixes it — it never switches silently. With no setup
// given it picks the setup that fits clearly better and returns the evidence as notes (and the
// readings poses cannot tell apart from it, convention_diagnosis.h); when neither fits clearly
// better it refuses and asks for the setup.
//
// The texts name the caller's controls through ConventionWords: by default this library's own
// terms (the setup, the unit of unsuffixed lengths, inverting a file's poses on reading); a
// command line passes its flags instead (hecal's: apps/hecal/conventions.cc), so that every
// message names what its user typed.
//
// Errors (InputError): invalid options (RequireValid, core/options_check.h); no setup given and
// fewer than 3 stations (source ConventionCheckOptions.setup); a mistake that fits clearly better
// (source: the file to fix, or ConventionCheckOptions.setup when the setup is the fix); no setup
// given and neither setup fits clearly better (ConventionCheckOptions.setup). With fewer than 3
// stations and a setup given nothing is compared: the solver reports the degeneracy.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "hecal/handeye/convention_diagnosis.h"
#include "hecal/handeye/problem.h"
#include "hecal/handeye/station_consensus.h"

namespace hecal::handeye {

// The caller's words for the controls that fix a mistake. Each is used as written below.
struct ConventionWords {
  // The setup control, followed by a setup name or `auto`: "run with setup eye-to-hand".
  std::string setup = "setup";
  // The unit of lengths without a unit suffix, followed by the unit: "give units mm when both
  // files are in mm".
  std::string units = "units";
  // Inverting each file's poses on reading, and not inverting them.
  std::string invert_robot = "invert the robot poses on reading";
  std::string keep_robot = "do not invert the robot poses on reading";
  std::string invert_camera = "invert the camera poses on reading";
  std::string keep_camera = "do not invert the camera poses on reading";
  // A command that rewrites a file of 12/16-number lines as a pose table, followed by the file,
  // `units` and the unit; empty: none is named.
  std::string import_matrix_lines;
};

struct ConventionCheckOptions {
  std::optional<Setup> setup;  // nullopt: pick the setup the data fit
  // Of the outlier rejection; the check scores at most 300 hypotheses on at most 300 stations
  // (it needs residual levels, not the best estimate).
  ConsensusOptions consensus;
  std::string robot_source;          // the robot file, named in errors
  std::string camera_source;         // the camera file (unused when data.camera_from_images)
  bool robot_inverted = false;       // the caller inverted the robot file's poses on reading
  bool camera_inverted = false;      // likewise the camera file's
  bool robot_matrix_lines = false;   // the robot file is 12/16-number lines (no header, no unit)
  bool camera_matrix_lines = false;  // likewise the camera file
  ConventionWords words;

  // core/options_check.h: the consensus options (ConsensusOptions::IsValid).
  bool IsValid(std::string* why) const;
};

struct ConventionCheck {
  Setup setup = Setup::kEyeInHand;  // given, or picked
  std::vector<std::string> notes;   // with no setup given: the evidence for the one picked
};

// `data.setup` is ignored: the setup is options.setup, or picked. Throws as listed above.
ConventionCheck CheckConventions(PoseData data, const ConventionCheckOptions& options);

}  // namespace hecal::handeye
