// The contour paper's experiments (docs/contour.md#the-experiments; the contour paper §V, Figs.
// 2–4): how precisely the camera motion is recovered from a contour, and whether the Unscented
// Transform's 13 points predict the uncertainty a 5000-sample Monte Carlo measures.
//
// Setting (the paper's, by default): a planar target 5000 mm in front of a camera with f = 50 mm;
// pure motions along one axis of the target-centred frame (affine_pose.h), swept from `from` to
// `to` in `steps` values; Gaussian noise of σ = 0.5 px on each coordinate of the perspective
// projection of the control points (perspective_view.h, so weak perspective's model error is in
// every result). For each value:
//  - Monte Carlo (the ground truth): `samples` noisy projections, each fitted (shape_space.h) and
//    turned into a pose (affine_pose.h, zyx); their mean error against the true motion, standard
//    deviation and covariance;
//  - UT: the 13 sigma points of S ~ (S̄, Σ_S), S̄ the fit of the noise-free projection and
//    Σ_S = σ²(WᵀW)⁻¹. The paper estimated Σ_S by Monte Carlo; because the fit is linear in the
//    points this is its exact value, so the UT's input does not share the Monte Carlo's sampling
//    error (the test checks the two agree);
//  - the bias flag of pose_uncertainty.h.
// The sensor is not given in the paper; the default pixel is 8.3 µm (a 768 × 576, 1/2-inch CCD of
// the period: 6.4 × 4.8 mm, so a 250 mm lateral motion at 5 m moves the target's image 2.5 mm, from
// the centre to near the edge, as the paper describes). The default target (DefaultTarget) is an
// irregular closed contour of 12 control points; its curve spans 222 × 125 mm (268 × 151 px at
// 5 m).
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hecal/contour/affine_pose.h"
#include "hecal/contour/pose_uncertainty.h"
#include "hecal/geometry/types.h"

namespace hecal::contour {

enum class StudyMotion { kTx, kTy, kTz, kRx, kRy, kRz };
std::optional<StudyMotion> ParseStudyMotion(std::string_view name);  // tx ty tz rx ry rz
std::string_view StudyMotionName(StudyMotion motion);
bool IsRotation(StudyMotion motion);

// The built-in target: 12 control points (mm, target plane) of an irregular closed contour,
// ρ(a) = 1 + 0.18 cos 2a + 0.12 sin(3a + 0.5) scaled to 100 × 75 mm, a = 2πk/12, centred so
// that its control points average to the origin (the centre of the motions).
Eigen::Matrix2Xd DefaultTarget();

struct ContourStudyOptions {
  static constexpr int kMaxSteps = 10000;
  static constexpr int kMaxSamples = 1000000;
  static constexpr std::int64_t kMaxSolves = 100000000;  // steps × samples
  static constexpr double kMaxPixelNoise = 100.0;  // px

  StudyMotion motion = StudyMotion::kTx;
  double from = 0.0;  // mm or degrees
  double to = 250.0;
  int steps = 11;
  double pixel_noise = 0.5;  // σ per coordinate, px
  double focal_mm = 50.0;
  double z0_mm = 5000.0;
  double pixel_size_mm = 0.0083;
  Eigen::Matrix2Xd target = DefaultTarget();  // mm
  int samples = 5000;
  std::uint64_t seed = 1;
  int threads = 0;
  UnscentedPoseOptions unscented;
  int keep_samples = 0;  // Monte Carlo poses kept per step (for plots)

  // True when usable, else false with "ContourStudyOptions.<field>: problem (fix: …)"
  // (core/options_check.h): focal, z0 and pixel size positive; pixel noise 0 … 100 px; from and
  // to finite, an out-of-plane rotation within (−90°, 90°), Tz above −Z0; steps 1 … 10000 (2 or
  // more for a range); samples 2 … 10^6 with steps × samples ≤ 10^8; threads 0 … 256; at least 4
  // target control points; the UT parameters valid for 6 dimensions.
  bool IsValid(std::string* why) const;
};

// Pose parameters are zyx (Tx, Ty, Tz, Rx, Ry, Rz): mm and radians.
struct StudyStep {
  double value = 0.0;  // the motion (mm or degrees)
  Vector6d truth;      // CanonicalPose of the true motion
  Vector6d mc_mean_error;
  Vector6d mc_sd;
  Matrix6d mc_covariance;
  Vector6d mc_sd_std_error;
  int mc_failures = 0;
  Vector6d ut_mean_error;
  Vector6d ut_sd;
  Matrix6d ut_covariance;
  Vector6d pose_of_mean_error;  // f(S̄) − truth
  std::array<bool, 6> bias{};
  Vector6d shape_mean;                // S̄ (px)
  Matrix6d shape_covariance;          // Σ_S
  std::vector<Vector6d> mc_poses;     // the first keep_samples Monte Carlo poses
  std::vector<Vector6d> sigma_poses;  // the UT's transformed sigma points
};

// Throws hecal::InputError when !options.IsValid, DegenerateError for collinear control points.
std::vector<StudyStep> RunContourStudy(const ContourStudyOptions& options);

// The camera of the study in pixels: f = focal_mm / pixel_size_mm, Z0 in mm.
ContourCamera StudyCamera(const ContourStudyOptions& options);
// The true motion at `value` (mm or degrees) of `motion`.
void StudyMotionPose(StudyMotion motion, double value, Eigen::Matrix3d* rotation,
                     Eigen::Vector3d* translation);

}  // namespace hecal::contour
