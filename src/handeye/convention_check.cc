// The convention check before a calibration: see convention_check.h.
#include "hecal/handeye/convention_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "hecal/core/error.h"
#include "hecal/core/options_check.h"

namespace hecal::handeye {
namespace {

// The InputError source when the setup is what to change.
constexpr const char* kSetupField = "ConventionCheckOptions.setup";

// "0.78 deg / 1.3 mm" (lengths of 1 m and more in m).
std::string ResidualText(double rotation_rad, double translation_m) {
  char text[96];
  const double degrees = rotation_rad * 180.0 / std::numbers::pi;
  if (std::abs(translation_m) >= 1.0) {
    std::snprintf(text, sizeof text, "%.3g deg / %.3g m", degrees, translation_m);
  } else {
    std::snprintf(text, sizeof text, "%.3g deg / %.3g mm", degrees, translation_m * 1e3);
  }
  return text;
}

std::string Metres(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g m", value);
  return text;
}

// The diagnosis needs residual levels, not the best estimate: fewer hypotheses than the outlier
// rejection, scored on fewer stations.
ConsensusOptions DiagnosisOptions(const ConsensusOptions& options) {
  ConsensusOptions diagnosis = options;
  diagnosis.max_hypotheses = std::min(options.max_hypotheses, 300);
  diagnosis.max_scored_stations = std::min(options.max_scored_stations, 300);
  return diagnosis;
}

std::string FitText(const ConventionFit& fit) {
  if (!fit.solved) return "no three stations fixing X";
  return "median station residual " + ResidualText(fit.median_rotation, fit.median_translation);
}

std::string Where(Setup setup) {
  return setup == Setup::kEyeInHand ? "on the robot" : "fixed";
}

std::string RobotInverseFix(const ConventionCheckOptions& options) {
  return options.robot_inverted
             ? options.words.keep_robot
             : options.words.invert_robot + " (the robot file holds T_gripper_base)";
}

std::string CameraInverseFix(const ConventionCheckOptions& options) {
  return options.camera_inverted
             ? options.words.keep_camera
             : options.words.invert_camera + " (the camera file holds T_target_camera)";
}

// The fix for a file whose lengths fit as `unit` ("mm" or "m").
std::string UnitFix(const std::string& file, bool matrix_lines, const std::string& unit,
                    const ConventionWords& words) {
  const std::string both =
      ", or give " + words.units + " " + unit + " when both files are in " + unit;
  if (matrix_lines) {
    const std::string import = words.import_matrix_lines.empty()
                                   ? std::string()
                                   : " (" + words.import_matrix_lines + " " + file + " " +
                                         words.units + " " + unit + " ...)";
    return "write " + file + " as a pose CSV in " + unit + import + both;
  }
  const std::string suffix = unit == "mm" ? "x_mm,y_mm,z_mm" : "x_m,y_m,z_m";
  return "name the unit in the header of " + file + " (" + suffix + ")" + both;
}

// The error for an alternative that fits clearly better than the data as given.
[[noreturn]] void Refuse(const PoseData& data, const ConventionFit& given,
                         const ConventionFit& better, const ConventionCheckOptions& options) {
  const ConventionWords& words = options.words;
  const std::string evidence = ": " + FitText(better) + " against " + FitText(given) +
                               " as given (" + std::string(SetupName(given.setup)) + ")";
  const std::string& robot = options.robot_source;
  const std::string& camera = options.camera_source;
  switch (better.convention) {
    case Convention::kOtherSetup: {
      // Poses alone cannot tell the other setup from an inverted file (convention_diagnosis.h);
      // the reading with the hand-mounted part nearer the flange comes first.
      const std::string given_setup(SetupName(given.setup));
      const std::string other(SetupName(better.setup));
      if (RobotInversionReading(better)) {
        throw InputError(robot, 0,
                         "these data fit the robot poses inverted (T_gripper_base) with " +
                             words.setup + " " + given_setup + evidence,
                         RobotInverseFix(options) + "; or, if the camera is " +
                             Where(better.setup) + ", run with " + words.setup + " " + other +
                             " (poses alone cannot tell these apart)");
      }
      const std::string camera_reading =
          data.camera_from_images
              ? std::string()
              : ", or the camera " + Where(given.setup) + " (" + given_setup + ") with " +
                    (options.camera_inverted ? "the camera poses not inverted"
                                             : "the camera poses inverted (T_target_camera)");
      const std::string camera_fix = data.camera_from_images ? std::string()
                                                             : "; if it is " + Where(given.setup) +
                                                                   ", " + CameraInverseFix(options);
      throw InputError(kSetupField, 0,
                       "these data fit the camera " + Where(better.setup) + " (" + other + ")" +
                           camera_reading + evidence,
                       "if the camera is " + Where(better.setup) + ", run with " + words.setup +
                           " " + other + camera_fix + " (poses alone cannot tell these apart)");
    }
    case Convention::kRobotMillimetres:
    case Convention::kRobotMetres:
    case Convention::kCameraMillimetres:
    case Convention::kCameraMetres: {
      const bool is_robot = better.convention == Convention::kRobotMillimetres ||
                            better.convention == Convention::kRobotMetres;
      const bool millimetres = better.convention == Convention::kRobotMillimetres ||
                               better.convention == Convention::kCameraMillimetres;
      const std::string& file = is_robot ? robot : camera;
      throw InputError(
          file, 0,
          std::string(is_robot ? "the robot" : "the camera") + " lengths fit as " +
              (millimetres ? "millimetres, not metres" : "metres, not millimetres") + evidence,
          UnitFix(file, is_robot ? options.robot_matrix_lines : options.camera_matrix_lines,
                  millimetres ? "mm" : "m", words));
    }
    case Convention::kRobotQuaternionShiftedLeft:
    case Convention::kRobotQuaternionShiftedRight:
    case Convention::kCameraQuaternionShiftedLeft:
    case Convention::kCameraQuaternionShiftedRight: {
      const bool is_robot = better.convention == Convention::kRobotQuaternionShiftedLeft ||
                            better.convention == Convention::kRobotQuaternionShiftedRight;
      throw InputError(
          is_robot ? robot : camera, 0,
          "these data fit " + std::string(ConventionName(better.convention)) + evidence,
          "name the quaternion columns in the order the values are written (e.g. "
          "qx,qy,qz,qw for x, y, z, w)");
    }
    case Convention::kAsGiven:
      break;
  }
  throw InputError(kSetupField, 0,
                   "these data fit " + std::string(ConventionName(better.convention)) + evidence,
                   "");
}

}  // namespace

bool ConventionCheckOptions::IsValid(std::string* why) const {
  return consensus.IsValid(why);
}

ConventionCheck CheckConventions(PoseData data, const ConventionCheckOptions& options) {
  RequireValid(options);
  const ConventionWords& words = options.words;
  const ConsensusOptions diagnosis_options = DiagnosisOptions(options.consensus);
  ConventionCheck check;
  if (data.T_base_gripper.size() < 3) {  // nothing to compare: the solver reports the degeneracy
    if (!options.setup) {
      throw InputError(
          kSetupField, 0,
          words.setup + " auto needs at least 3 stations to tell the setups apart, " + "got " +
              std::to_string(data.T_base_gripper.size()),
          "record more stations, or give " + words.setup + " eye-in-hand or eye-to-hand");
    }
    check.setup = *options.setup;
    return check;
  }
  if (options.setup) {
    data.setup = *options.setup;
  } else {
    data.setup = Setup::kEyeInHand;
    const ConventionFit in_hand = FitConvention(data, Convention::kAsGiven, diagnosis_options);
    const ConventionFit to_hand = FitConvention(data, Convention::kOtherSetup, diagnosis_options);
    const ConventionFit* chosen = nullptr;
    const ConventionFit* other = nullptr;
    if (FitsClearlyBetter(to_hand, in_hand)) {
      chosen = &to_hand, other = &in_hand;
    } else if (FitsClearlyBetter(in_hand, to_hand)) {
      chosen = &in_hand, other = &to_hand;
    } else {
      // Neither setup fits clearly better: maybe another mistake explains the data.
      const ConventionDiagnosis diagnosis = DiagnoseConventions(data, diagnosis_options);
      if (diagnosis.better && diagnosis.better->convention != Convention::kOtherSetup) {
        Refuse(data, diagnosis.given, *diagnosis.better, options);
      }
      throw InputError(kSetupField, 0,
                       words.setup +
                           " auto cannot tell the setup from these data: " + FitText(in_hand) +
                           " as eye-in-hand, " + FitText(to_hand) + " as eye-to-hand",
                       "give " + words.setup + " eye-in-hand (camera on the robot) or " +
                           words.setup + " eye-to-hand (camera fixed)");
    }
    data.setup = chosen->setup;
    const std::string name(SetupName(chosen->setup));
    check.notes.push_back(words.setup + " auto chose " + name + ": " + FitText(*chosen) +
                          " against " + FitText(*other) + " as " +
                          std::string(SetupName(other->setup)));
    // The readings with the same fit (convention_diagnosis.h).
    if (!data.camera_from_images) {
      check.notes.push_back("the same data fit the camera " + Where(other->setup) + " (" +
                            std::string(SetupName(other->setup)) +
                            ") with the camera poses inverted: poses alone cannot tell these "
                            "apart, so check that the camera is " +
                            Where(chosen->setup));
    }
    // Read as the other setup with the robot poses inverted, the chosen fit has the same
    // (X, Z) with the hand-mounted and the fixed part exchanged.
    const bool in = chosen->setup == Setup::kEyeInHand;
    const Pose& hand = in ? chosen->solution.X : chosen->solution.Z;
    const Pose& cell = in ? chosen->solution.Z : chosen->solution.X;
    if (hand.translation().norm() > cell.translation().norm()) {
      check.notes.push_back("read as " + name + " the " + (in ? "camera" : "target") + " is " +
                            Metres(hand.translation().norm()) +
                            " from the flange, further than the " + (in ? "target" : "camera") +
                            " is from the base: if the camera is " + Where(other->setup) +
                            " and the robot file holds T_gripper_base, run " + "with " +
                            words.setup + " " + std::string(SetupName(other->setup)) + " and " +
                            RobotInverseFix(options));
    }
  }
  check.setup = data.setup;
  const ConventionDiagnosis diagnosis = DiagnoseConventions(data, diagnosis_options);
  if (diagnosis.better) Refuse(data, diagnosis.given, *diagnosis.better, options);
  return check;
}

}  // namespace hecal::handeye
