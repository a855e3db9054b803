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
#include "hecal/core/split_mix.h"
#include "hecal/uncertainty/monte_carlo.h"

namespace hecal::contour {
namespace {

constexpr double kRadians = std::numbers::pi / 180.0;

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

void ValidateStudyOptions(const ContourStudyOptions& o) {
  const auto positive = [](double x, const char* field, const char* what) {
    if (!Finite(x) || !(x > 0.0)) {
      throw InputError(field, 0, std::string(what) + " must be a positive number",
                       std::string("give ") + what);
    }
  };
  positive(o.focal_mm, "ContourStudyOptions.focal_mm", "the focal length (mm)");
  positive(o.z0_mm, "ContourStudyOptions.z0_mm", "the initial distance (mm)");
  positive(o.pixel_size_mm, "ContourStudyOptions.pixel_size_mm", "the pixel size (mm)");
  if (!Finite(o.pixel_noise) || o.pixel_noise < 0.0) {
    throw InputError("ContourStudyOptions.pixel_noise", 0, "the pixel noise must be ≥ 0",
                     "give σ in pixels, e.g. 0.5");
  }
  if (!Finite(o.from) || !Finite(o.to)) {
    throw InputError("ContourStudyOptions.from", 0, "the motion range must be finite numbers",
                     "give e.g. from 0 to 250");
  }
  if (o.steps < 1 || (o.steps == 1 && o.from != o.to)) {
    throw InputError("ContourStudyOptions.steps", 0,
                     "need at least 2 steps for a range (1 when from = to)",
                     "give e.g. --steps 11");
  }
  if (o.samples < 2) {
    throw InputError("ContourStudyOptions.samples", 0, "the Monte Carlo needs at least 2 samples",
                     "give e.g. 5000");
  }
  if (o.threads < 0)
    throw InputError("ContourStudyOptions.threads", 0, "must be ≥ 0", "0 uses every core");
  if (IsRotation(o.motion) && o.motion != StudyMotion::kRz &&
      (std::abs(o.from) >= 90.0 || std::abs(o.to) >= 90.0)) {
    throw InputError("ContourStudyOptions.to", 0,
                     "an out-of-plane rotation must stay below 90° (the plane is then "
                     "seen edge-on: the tilt θ is beyond its range [0°, 90°))",
                     "give angles in (−90°, 90°)");
  }
  if (o.motion == StudyMotion::kTz && (o.from <= -o.z0_mm || o.to <= -o.z0_mm)) {
    throw InputError("ContourStudyOptions.to", 0,
                     "Tz must stay above −Z0 (the target would be behind the camera)",
                     "give Tz > −" + std::to_string(o.z0_mm));
  }
  // The target itself: a closed contour whose control points span an area.
  if (o.target.cols() < 4) {
    throw InputError("ContourStudyOptions.target", 0, "the target needs at least 4 control points",
                     "give 4 or more x,y rows");
  }
  const ShapeSpace check(o.target);  // throws DegenerateError for collinear control points
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
      *rotation = RotationZyx(value * kRadians, 0.0, 0.0);
      break;
    case StudyMotion::kRy:
      *rotation = RotationZyx(0.0, value * kRadians, 0.0);
      break;
    case StudyMotion::kRz:
      *rotation = RotationZyx(0.0, 0.0, value * kRadians);
      break;
  }
}

std::vector<StudyStep> RunContourStudy(const ContourStudyOptions& options) {
  ValidateStudyOptions(options);
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
