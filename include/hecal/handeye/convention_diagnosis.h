// Which pose conventions the data fit: the setup and files as given, against the mistakes users
// make with them, one at a time. A wrong setup or an inverted file gives residuals of tens of
// degrees, which the noise-aware degeneracy test then reads as "the rotations differ only by
// noise" — so hecal compares the conventions before it solves, and says which one fits.
//
// Alternatives (each applied to the poses as read, metres and radians):
//   kOtherSetup          eye-in-hand ↔ eye-to-hand: A_i → A_i⁻¹ (problem.h). Three mistakes
//                        give exactly these equations, and poses alone cannot tell them apart:
//                          - the other setup;
//                          - the robot poses inverted (T_gripper_base given for T_base_gripper),
//                            same setup: the same (X, Z);
//                          - the camera poses inverted (T_target_camera given), same setup: X and
//                            Z swapped, since A_i⁻¹ X B_i = Z ⇔ A_i Z B_i⁻¹ = X. Physically it is
//                            the other setup with the names camera and target exchanged.
//                        Inverting both files changes nothing that poses can see (X and Z swap).
//                        RobotInversionReading says which reading puts the hand-mounted part
//                        (X for eye-in-hand, Z for eye-to-hand) nearer the flange.
//   kRobotMillimetres    robot translations × 1e-3 (millimetres read as metres) — and
//   kRobotMetres         × 1e3 (metres read as millimetres), only when the robot file does not
//                        name its unit; likewise kCameraMillimetres / kCameraMetres
//   kRobotQuaternionShifted{Left,Right}   the robot file's quaternion columns hold the
//                        components one place off the names of its header (w,x,y,z values
//                        under x,y,z,w names, or the reverse) — only for quaternion files;
//                        likewise for the camera file
// Both files in the same wrong unit scale X, Z and the residuals alike and fit as well as the
// truth: that mistake is caught by plausibility (estimation/plausibility.h), not here.
//
// Fit measure: the median station residual (rotation angle, translation length) at the
// consensus estimate of each alternative (station_consensus.h: robust to fewer than half gross
// outliers, no noise level needed), the translation relative to the alternative's own length
// scale (camera-to-target distance), so that a change of unit compares like with like. An
// alternative fits clearly better than the data as given when one median is at least
// kClearlyBetter (4) times smaller and the other no more than kNotWorse (1.5) times larger,
// medians floored at 1e-9 rad and 1e-9 of the length scale. For correct data every
// alternative is far worse (a wrong inversion leaves residuals of the order of the rotations
// between stations), so this never fires on them: 0 false alarms in 1200 simulated correct data
// sets, and 1077 of 1080 mistaken ones named (convention_diagnosis_test; docs/troubleshooting.md).
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "hecal/geometry/types.h"
#include "hecal/handeye/problem.h"
#include "hecal/handeye/station_consensus.h"

namespace hecal::handeye {

enum class Convention {
  kAsGiven,
  kOtherSetup,
  kRobotMillimetres,
  kRobotMetres,
  kCameraMillimetres,
  kCameraMetres,
  kRobotQuaternionShiftedLeft,
  kRobotQuaternionShiftedRight,
  kCameraQuaternionShiftedLeft,
  kCameraQuaternionShiftedRight,
};

inline constexpr double kClearlyBetter = 4.0;
inline constexpr double kNotWorse = 1.5;

// The data as read, and what the files left open.
struct PoseData {
  Setup setup = Setup::kEyeInHand;
  std::vector<Pose> T_base_gripper;   // as read (after any inversion the user asked for)
  std::vector<Pose> T_camera_target;  // as read
  bool robot_unit_named = true;       // false: the unit came from a flag or the default
  bool camera_unit_named = true;
  bool robot_quaternions = false;  // the robot file's rotations were quaternion columns
  bool camera_quaternions = false;
  // The camera poses come from PnP on images (T_camera_target in the target's own unit): no
  // camera-side alternative applies.
  bool camera_from_images = false;
};

struct ConventionFit {
  Convention convention = Convention::kAsGiven;
  Setup setup = Setup::kEyeInHand;  // the setup this fit solved (kOtherSetup: the other one)
  bool solved = false;              // false: no three stations fixed X (degenerate)
  double median_rotation = 0.0;     // radians
  double median_translation = 0.0;  // metres, in the alternative's own lengths
  double length_scale = 1.0;        // LengthScale of the alternative's problem, metres
  Solution solution;                // the consensus estimate (X, Z of `setup`)
};

struct ConventionDiagnosis {
  ConventionFit given;
  std::vector<ConventionFit> alternatives;  // every alternative that applies, in enum order
  // The alternative that fits clearly better than the data as given, if any: the best by the
  // product of the two median ratios; among those within a factor 2 of it (a robot in metres
  // read as millimetres fits exactly as well as the camera in millimetres: only the ratio of the
  // units shows), the one whose median robot reach and camera-to-target distance are nearest
  // 1 m (in decades).
  std::optional<ConventionFit> better;
};

// The data with one mistake undone (kAsGiven: unchanged; kOtherSetup: the other setup).
PoseData ApplyConvention(const PoseData& data, Convention convention);

// The fit of one convention (DegenerateError caught: solved = false).
ConventionFit FitConvention(const PoseData& data, Convention convention,
                            const ConsensusOptions& options);

// The alternatives that apply to `data` (units and quaternion orders only where the files left
// them open), fitted, compared with the data as given.
ConventionDiagnosis DiagnoseConventions(const PoseData& data, const ConsensusOptions& options);

// The rule above; an unsolved `candidate` never fits better, an unsolved `reference` is beaten by
// any solved candidate.
bool FitsClearlyBetter(const ConventionFit& candidate, const ConventionFit& reference);

// For a kOtherSetup fit: true when reading it as the robot poses inverted (the setup as given)
// puts the hand-mounted part nearer the flange than the other part is to the base — a camera or
// target on the hand is the shorter transform. False: the other setup, or equally the camera
// poses inverted, is the plausible reading.
bool RobotInversionReading(const ConventionFit& other_setup_fit);

std::string_view ConventionName(Convention convention);  // e.g. "camera poses inverted"

}  // namespace hecal::handeye
