// The contour paper's experiments: see contour_study.h.
#include "hecal/contour/contour_study.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "hecal/contour/perspective_view.h"
#include "hecal/contour/shape_space.h"
#include "hecal/core/error.h"
#include "hecal/core/number_text.h"
#include "hecal/core/options_check.h"
#include "hecal/core/split_mix.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/uncertainty/monte_carlo.h"

namespace hecal::contour {
namespace {

struct MotionInfo {
  StudyMotion motion;
  std::string_view name;
};
constexpr std::array<MotionInfo, 6> kMotions = {{{StudyMotion::kTx, "tx"},
                                                 {StudyMotion::kTy, "ty"},
                                                 {StudyMotion::kTz, "tz"},
                                                 {StudyMotion::kRx, "rx"},
                                                 {StudyMotion::kRy, "ry"},
                                                 {StudyMotion::kRz, "rz"}}};

bool Finite(double x) {
  return std::isfinite(x);
}

}  // namespace

std::optional<StudyMotion> ParseStudyMotion(std::string_view name) {
  for (const MotionInfo& info : kMotions) {
    if (info.name == name) return info.motion;
  }
  return std::nullopt;
}

std::string_view StudyMotionName(StudyMotion motion) {
  for (const MotionInfo& info : kMotions) {
    if (info.motion == motion) return info.name;
  }
  return "?";
}

bool IsRotation(StudyMotion motion) {
  return motion == StudyMotion::kRx || motion == StudyMotion::kRy || motion == StudyMotion::kRz;
}

Eigen::Matrix2Xd DefaultTarget() {
  constexpr int kPoints = 12;
  Eigen::Matrix2Xd Q(2, kPoints);
  for (int k = 0; k < kPoints; ++k) {
    const double a = 2.0 * std::numbers::pi * k / kPoints;
    const double rho = 1.0 + 0.18 * std::cos(2.0 * a) + 0.12 * std::sin(3.0 * a + 0.5);
    Q.col(k) << 100.0 * rho * std::cos(a), 75.0 * rho * std::sin(a);
  }
  Q.colwise() -= Q.rowwise().mean();
  return Q;
}

bool ContourStudyOptions::IsValid(std::string* why) const {
  const auto positive = [why](double x, const char* field, const char* what) {
    return (Finite(x) && x > 0.0) ||
           Invalid(why, field, std::string(what) + " must be a positive number",
                   std::string("give ") + what);
  };
  if (!positive(focal_mm, "ContourStudyOptions.focal_mm", "the focal length (mm)") ||
      !positive(z0_mm, "ContourStudyOptions.z0_mm", "the initial distance (mm)") ||
      !positive(pixel_size_mm, "ContourStudyOptions.pixel_size_mm", "the pixel size (mm)")) {
    return false;
  }
  if (!(pixel_noise >= 0.0 && pixel_noise <= kMaxPixelNoise)) {
    return Invalid(
        why, "ContourStudyOptions.pixel_noise",
        "must be 0 to " + NumberText(kMaxPixelNoise) + " px, got " + NumberText(pixel_noise),
        "give the noise of one image coordinate in pixels, e.g. 0.5");
  }
  if (!Finite(from) || !Finite(to)) {
    return Invalid(why, "ContourStudyOptions.from", "the motion range must be finite numbers",
                   "give e.g. from 0 to 250");
  }
  if (steps < 1 || steps > kMaxSteps) {
    return Invalid(why, "ContourStudyOptions.steps",
                   "must be a whole number from 1 to " + std::to_string(kMaxSteps) + ", got " +
                       std::to_string(steps),
                   "give the number of motion values in that range");
  }
  if (steps == 1 && from != to) {
    return Invalid(why, "ContourStudyOptions.steps",
                   "need at least 2 steps for a range (1 when from = to)", "give e.g. 11 steps");
  }
  if (samples < 2 || samples > kMaxSamples) {
    return Invalid(why, "ContourStudyOptions.samples",
                   "must be a whole number from 2 to " + std::to_string(kMaxSamples) + ", got " +
                       std::to_string(samples),
                   "give the number of Monte Carlo samples per step in that range");
  }
  if (std::int64_t{samples} * steps > kMaxSolves) {
    return Invalid(why, "ContourStudyOptions.samples",
                   std::to_string(steps) + " steps x " + std::to_string(samples) +
                       " samples is more than " + std::to_string(kMaxSolves) +
                       " Monte Carlo solves",
                   "give fewer steps or samples");
  }
  if (!ThreadCountValid(threads, "ContourStudyOptions.threads", why)) return false;
  if (IsRotation(motion) && motion != StudyMotion::kRz &&
      (std::abs(from) >= 90.0 || std::abs(to) >= 90.0)) {
    return Invalid(why, "ContourStudyOptions.to",
                   "an out-of-plane rotation must stay below 90° (the plane is then "
                   "seen edge-on: the tilt θ is beyond its range [0°, 90°))",
                   "give angles in (−90°, 90°)");
  }
  if (motion == StudyMotion::kTz && (from <= -z0_mm || to <= -z0_mm)) {
    return Invalid(why, "ContourStudyOptions.to",
                   "Tz must stay above −Z0 (the target would be behind the camera)",
                   "give Tz > −" + std::to_string(z0_mm));
  }
  if (target.cols() < 4) {
    return Invalid(why, "ContourStudyOptions.target", "the target needs at least 4 control points",
                   "give 4 or more x,y rows");
  }
  std::string ut_why;
  if (!unscented.unscented.IsValid(6, &ut_why)) {
    return Invalid(why, "ContourStudyOptions.unscented", ut_why, "give w0 < 1 (default 0)");
  }
  return true;
}

ContourCamera StudyCamera(const ContourStudyOptions& options) {
  return ContourCamera{options.focal_mm / options.pixel_size_mm, options.z0_mm};
}

void StudyMotionPose(StudyMotion motion, double value, Eigen::Matrix3d* rotation,
                     Eigen::Vector3d* translation) {
  *rotation = Eigen::Matrix3d::Identity();
  *translation = Eigen::Vector3d::Zero();
  switch (motion) {
    case StudyMotion::kTx:
      translation->x() = value;
      break;
    case StudyMotion::kTy:
      translation->y() = value;
      break;
    case StudyMotion::kTz:
      translation->z() = value;
      break;
    case StudyMotion::kRx:
      *rotation = RotationZyx(value * kRadiansPerDegree, 0.0, 0.0);
      break;
    case StudyMotion::kRy:
      *rotation = RotationZyx(0.0, value * kRadiansPerDegree, 0.0);
      break;
    case StudyMotion::kRz:
      *rotation = RotationZyx(0.0, 0.0, value * kRadiansPerDegree);
      break;
  }
}

std::vector<StudyStep> RunContourStudy(const ContourStudyOptions& options) {
  RequireValid(options);
  const ShapeSpace check(options.target);  // throws DegenerateError for collinear control points
  const ContourCamera camera = StudyCamera(options);
  constexpr RotationForm kForm = RotationForm::kZyx;
  const Eigen::Matrix2Xd template_image = TemplateImage(options.target, camera);
  const ShapeSpace space(template_image);
  const Matrix6d shape_covariance = space.FitCovariance(options.pixel_noise);
  const Eigen::Index points = options.target.cols();

  std::vector<StudyStep> steps;
  for (int i = 0; i < options.steps; ++i) {
    StudyStep step;
    step.value = options.steps == 1
                     ? options.from
                     : options.from + (options.to - options.from) * i / (options.steps - 1);
    Eigen::Matrix3d R;
    Eigen::Vector3d T;
    StudyMotionPose(options.motion, step.value, &R, &T);
    step.truth = PoseParameters(CanonicalPose(R, T, kForm));
    const Eigen::Matrix2Xd image = ProjectPerspective(options.target, R, T, camera);
    step.shape_mean = space.Fit(image);
    step.shape_covariance = shape_covariance;

    // UT on (S̄, Σ_S).
    const ContourPoseUncertainty ut =
        UnscentedPose(step.shape_mean, shape_covariance, camera, kForm, options.unscented);
    const Vector6d reference = ut.parameters;
    step.ut_mean_error = PoseDifference(ut.mean, step.truth, kForm);
    step.ut_sd = ut.covariance.diagonal().cwiseMax(0.0).cwiseSqrt();
    step.ut_covariance = ut.covariance;
    step.pose_of_mean_error = PoseDifference(ut.parameters, step.truth, kForm);
    step.bias = ut.biased;
    step.sigma_poses = ut.sigma_poses;

    // Monte Carlo: noisy control points, fitted and solved, sample by sample.
    uncertainty::MonteCarloOptions mc;
    mc.samples = options.samples;
    mc.seed = SplitMix64(options.seed ^ SplitMix64(static_cast<std::uint64_t>(i)));
    mc.threads = options.threads;
    // The first keep_samples poses are kept for plots as they are drawn (each index is written by
    // one thread only); a failed sample throws before it is kept, as it is left out of the
    // statistics.
    std::vector<std::optional<Vector6d>> kept(
        static_cast<std::size_t>(std::clamp(options.keep_samples, 0, options.samples)));
    const auto sample = [&](int k) -> Eigen::VectorXd {
      const Eigen::VectorXd z =
          uncertainty::StandardNormalSample(mc.seed, k, 2 * static_cast<int>(points));
      const Eigen::Matrix2Xd noisy =
          image + options.pixel_noise * Eigen::Map<const Eigen::Matrix2Xd>(z.data(), 2, points);
      const Vector6d pose = PoseParametersNear(space.Fit(noisy), camera, kForm, reference);
      if (static_cast<std::size_t>(k) < kept.size()) kept[static_cast<std::size_t>(k)] = pose;
      return pose;
    };
    const uncertainty::MonteCarloMoments<Eigen::VectorXd> moments =
        uncertainty::MonteCarloSamples<Eigen::VectorXd>(sample, Eigen::VectorXd(reference), mc);
    step.mc_mean_error = PoseDifference(moments.mean, step.truth, kForm);
    step.mc_covariance = moments.covariance;
    step.mc_sd = moments.covariance.diagonal().cwiseSqrt();
    step.mc_sd_std_error = moments.sd_std_error;
    step.mc_failures = moments.failures;
    for (const std::optional<Vector6d>& pose : kept) {
      if (pose) step.mc_poses.push_back(*pose);
    }
    steps.push_back(std::move(step));
  }
  return steps;
}

}  // namespace hecal::contour
