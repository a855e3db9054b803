// The convention check of `hecal calibrate`: see conventions.h.
#include "conventions.h"

#include <cmath>
#include <cstdio>
#include <numbers>

#include "hecal/core/error.h"

namespace hecal::cli {
namespace {

using handeye::Convention;
using handeye::ConventionFit;
using handeye::Setup;

// The diagnosis needs residual levels, not the best estimate: fewer hypotheses than the outlier
// rejection, scored on fewer stations.
handeye::ConsensusOptions DiagnosisOptions(const handeye::ConsensusOptions& options) {
  handeye::ConsensusOptions diagnosis = options;
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

std::string RobotInverseFix(const ConventionFlags& flags) {
  return flags.robot_inverse ? "leave out --robot-inverse"
                             : "add --robot-inverse (the robot file holds T_gripper_base)";
}

std::string CameraInverseFix(const ConventionFlags& flags) {
  return flags.camera_inverse ? "leave out --camera-inverse"
                              : "add --camera-inverse (the camera file holds T_target_camera)";
}

// The fix for a file whose lengths fit as `unit` ("mm" or "m").
std::string UnitFix(const std::string& file, bool matrix_lines, const std::string& unit) {
  const std::string suffix = unit == "mm" ? "x_mm,y_mm,z_mm" : "x_m,y_m,z_m";
  if (matrix_lines) {
    return "write " + file + " as a pose CSV in " + unit + " (hecal import --format matrix16 " +
           file + " --units " + unit + " ...), or give --units " + unit +
           " when both files are in " + unit;
  }
  return "name the unit in the header of " + file + " (" + suffix + "), or give --units " + unit +
         " when both files are in " + unit;
}

// The error for an alternative that fits clearly better than the data as given.
[[noreturn]] void Refuse(const ConventionFit& given, const ConventionFit& better,
                         const ConventionFlags& flags) {
  const std::string evidence = ": " + FitText(better) + " against " + FitText(given) +
                               " as given (" + std::string(handeye::SetupName(given.setup)) + ")";
  const std::string robot = flags.robot_file;
  const std::string camera = flags.camera_file;
  switch (better.convention) {
    case Convention::kOtherSetup: {
      // Poses alone cannot tell the other setup from an inverted file (convention_diagnosis.h);
      // the reading with the hand-mounted part nearer the flange comes first.
      const std::string given_setup(handeye::SetupName(given.setup));
      const std::string other(handeye::SetupName(better.setup));
      if (handeye::RobotInversionReading(better)) {
        throw InputError(flags.robot_file, 0,
                         "these data fit the robot poses inverted (T_gripper_base) with --setup " +
                             given_setup + evidence,
                         RobotInverseFix(flags) + "; or, if the camera is " + Where(better.setup) +
                             ", " + "run with --setup " + other +
                             " (poses alone cannot tell these apart)");
      }
      const std::string camera_reading =
          flags.camera_file.empty()
              ? std::string()
              : ", or the camera " + Where(given.setup) + " (" + given_setup + ") with " +
                    (flags.camera_inverse ? "the camera poses not inverted"
                                          : "the camera poses inverted (T_target_camera)");
      const std::string camera_fix =
          flags.camera_file.empty()
              ? std::string()
              : "; if it is " + Where(given.setup) + ", " + CameraInverseFix(flags);
      throw InputError("--setup", 0,
                       "these data fit the camera " + Where(better.setup) + " (" + other + ")" +
                           camera_reading + evidence,
                       "if the camera is " + Where(better.setup) + ", run with --setup " + other +
                           camera_fix + " (poses alone cannot tell these apart)");
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
          UnitFix(file, is_robot ? flags.robot_matrix_lines : flags.camera_matrix_lines,
                  millimetres ? "mm" : "m"));
    }
    case Convention::kRobotQuaternionShiftedLeft:
    case Convention::kRobotQuaternionShiftedRight:
    case Convention::kCameraQuaternionShiftedLeft:
    case Convention::kCameraQuaternionShiftedRight: {
      const bool is_robot = better.convention == Convention::kRobotQuaternionShiftedLeft ||
                            better.convention == Convention::kRobotQuaternionShiftedRight;
      throw InputError(
          is_robot ? robot : camera, 0,
          "these data fit " + std::string(handeye::ConventionName(better.convention)) + evidence,
          "name the quaternion columns in the order the values are written (e.g. "
          "qx,qy,qz,qw for x, y, z, w)");
    }
    case Convention::kAsGiven:
      break;
  }
  throw InputError(
      "--setup", 0,
      "these data fit " + std::string(handeye::ConventionName(better.convention)) + evidence, "");
}

std::string Metres(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g m", value);
  return text;
}

}  // namespace

bool HasQuaternionColumns(const io::PoseTable& table) {
  return table.rotation && table.rotation->kind == io::RotationFormat::Kind::kQuaternion;
}

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

ConventionCheck CheckConventions(handeye::PoseData data, std::optional<Setup> setup,
                                 const ConventionFlags& flags,
                                 const handeye::ConsensusOptions& options) {
  const handeye::ConsensusOptions diagnosis_options = DiagnosisOptions(options);
  ConventionCheck check;
  if (data.T_base_gripper.size() < 3) {  // nothing to compare: the solver reports the degeneracy
    if (!setup) {
      throw InputError("--setup", 0,
                       "--setup auto needs at least 3 stations to tell the setups apart, got " +
                           std::to_string(data.T_base_gripper.size()),
                       "record more stations, or give --setup eye-in-hand or eye-to-hand");
    }
    check.setup = *setup;
    return check;
  }
  if (setup) {
    data.setup = *setup;
  } else {
    data.setup = Setup::kEyeInHand;
    const ConventionFit in_hand =
        handeye::FitConvention(data, Convention::kAsGiven, diagnosis_options);
    const ConventionFit to_hand =
        handeye::FitConvention(data, Convention::kOtherSetup, diagnosis_options);
    const ConventionFit* chosen = nullptr;
    const ConventionFit* other = nullptr;
    if (handeye::FitsClearlyBetter(to_hand, in_hand)) {
      chosen = &to_hand, other = &in_hand;
    } else if (handeye::FitsClearlyBetter(in_hand, to_hand)) {
      chosen = &in_hand, other = &to_hand;
    } else {
      // Neither setup fits clearly better: maybe another mistake explains the data.
      const handeye::ConventionDiagnosis diagnosis =
          handeye::DiagnoseConventions(data, diagnosis_options);
      if (diagnosis.better && diagnosis.better->convention != Convention::kOtherSetup) {
        Refuse(diagnosis.given, *diagnosis.better, flags);
      }
      throw InputError("--setup", 0,
                       "--setup auto cannot tell the setup from these data: " + FitText(in_hand) +
                           " as eye-in-hand, " + FitText(to_hand) + " as eye-to-hand",
                       "give --setup eye-in-hand (camera on the robot) or --setup eye-to-hand "
                       "(camera fixed)");
    }
    data.setup = chosen->setup;
    const std::string name(handeye::SetupName(chosen->setup));
    check.notes.push_back("--setup auto chose " + name + ": " + FitText(*chosen) + " against " +
                          FitText(*other) + " as " + std::string(handeye::SetupName(other->setup)));
    // The readings with the same fit (convention_diagnosis.h).
    if (!flags.camera_file.empty()) {
      check.notes.push_back("the same data fit the camera " + Where(other->setup) + " (" +
                            std::string(handeye::SetupName(other->setup)) +
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
      check.notes.push_back(
          "read as " + name + " the " + (in ? "camera" : "target") + " is " +
          Metres(hand.translation().norm()) + " from the flange, further than the " +
          (in ? "target" : "camera") + " is from the base: if the camera is " +
          Where(other->setup) + " and the robot file holds T_gripper_base, run with --setup " +
          std::string(handeye::SetupName(other->setup)) + " and " + RobotInverseFix(flags));
    }
  }
  check.setup = data.setup;
  const handeye::ConventionDiagnosis diagnosis =
      handeye::DiagnoseConventions(data, diagnosis_options);
  if (diagnosis.better) Refuse(diagnosis.given, *diagnosis.better, flags);
  return check;
}

}  // namespace hecal::cli
