#include "hecal/estimation/calibration_covariance.h"

#include <stdexcept>

#include "hecal/core/error.h"
#include "hecal/core/limits.h"
#include "hecal/core/options_check.h"
#include "hecal/estimation/bound.h"
#include "hecal/estimation/ml.h"
#include "hecal/estimation/robust_loss.h"
#include "hecal/estimation/strobl.h"
#include "hecal/uncertainty/first_order.h"
#include "hecal/uncertainty/monte_carlo.h"
#include "hecal/uncertainty/unscented.h"

namespace hecal::estimation {
namespace {

using Poses = std::vector<Pose>;
using Matrix12d = Eigen::Matrix<double, 12, 12>;

// The measurements as one point of SE(3)^{2n}: (G_1 … G_n, B_1 … B_n) with G_i = T_base_gripper_i
// as the robot reported it (A_i, or A_i⁻¹ eye-to-hand: problem.h), so that the right
// perturbations are the noise model's (pose_sigma.h). Perturbing A_i itself would put the robot
// noise on the wrong side eye-to-hand, with a lever arm of the whole base–flange distance.
Pose RobotMeasurement(handeye::Setup setup, const Pose& A) {
  return setup == handeye::Setup::kEyeToHand ? A.inverse() : A;
}

Poses StackStations(const handeye::Problem& problem) {
  Poses stations;
  stations.reserve(2 * problem.A.size());
  for (const Pose& A : problem.A) stations.push_back(RobotMeasurement(problem.setup, A));
  stations.insert(stations.end(), problem.B.begin(), problem.B.end());
  return stations;
}

handeye::Problem UnstackStations(const handeye::Problem& like, const Poses& stations) {
  handeye::Problem problem = like;
  const size_t n = like.A.size();
  for (size_t i = 0; i < n; ++i) problem.A[i] = RobotMeasurement(like.setup, stations[i]);
  problem.B.assign(stations.begin() + static_cast<std::ptrdiff_t>(n), stations.end());
  return problem;
}

Eigen::MatrixXd InputCovariance(const StationNoise& noise) {
  const Eigen::Index n = static_cast<Eigen::Index>(noise.robot.size());
  Eigen::MatrixXd covariance = Eigen::MatrixXd::Zero(12 * n, 12 * n);
  for (Eigen::Index i = 0; i < n; ++i) {
    covariance.block<6, 6>(6 * i, 6 * i) = noise.robot[static_cast<size_t>(i)];
    covariance.block<6, 6>(6 * (n + i), 6 * (n + i)) = noise.camera[static_cast<size_t>(i)];
  }
  return covariance;
}

}  // namespace

std::optional<CovarianceMethod> ParseCovarianceMethod(std::string_view text) {
  if (text == "none") return CovarianceMethod::kNone;
  if (text == "linear") return CovarianceMethod::kLinear;
  if (text == "unscented") return CovarianceMethod::kUnscented;
  if (text == "montecarlo") return CovarianceMethod::kMonteCarlo;
  if (text == "information") return CovarianceMethod::kInformation;
  return std::nullopt;
}

std::string_view CovarianceMethodName(CovarianceMethod method) {
  switch (method) {
    case CovarianceMethod::kNone:
      return "none";
    case CovarianceMethod::kLinear:
      return "linear";
    case CovarianceMethod::kUnscented:
      return "unscented";
    case CovarianceMethod::kMonteCarlo:
      return "montecarlo";
    case CovarianceMethod::kInformation:
      return "information";
  }
  return "none";
}

CovarianceMethod DefaultCovarianceMethod(Method method, size_t stations) {
  if (Info(method).analytic_covariance) return CovarianceMethod::kLinear;
  return stations <= kMaxUnscentedStations ? CovarianceMethod::kUnscented
                                           : CovarianceMethod::kInformation;
}

bool CovarianceOptions::IsValid(std::string* why) const {
  if (samples < 2 || samples > kMaxCovarianceSamples) {
    return Invalid(why, "CovarianceOptions.samples",
                   "must be a whole number from 2 to " + std::to_string(kMaxCovarianceSamples) +
                       ", got " + std::to_string(samples),
                   "give the number of Monte Carlo samples in that range (e.g. 5000)");
  }
  if (!ThreadCountValid(threads, "CovarianceOptions.threads", why)) return false;
  return true;
}

void CheckCovarianceFits(CovarianceMethod method, Method solver, size_t stations) {
  const bool analytic = method == CovarianceMethod::kNone ||
                        method == CovarianceMethod::kInformation ||
                        (method == CovarianceMethod::kLinear && Info(solver).analytic_covariance);
  if (analytic || stations <= kMaxPropagatedStations) return;
  std::string problem(CovarianceMethodName(method));
  problem += " propagation needs a dense 12n x 12n input covariance: at most ";
  problem += std::to_string(kMaxPropagatedStations);
  problem += " stations, got ";
  problem += std::to_string(stations);
  std::string fix = "leave the covariance method unset (above ";
  fix += std::to_string(kMaxUnscentedStations);
  fix += " stations the default is information, O(n)) or choose information";
  throw InputError("CovarianceOptions.method", 0, problem, fix);
}

CalibrationCovariance FromMonteCarlo(const uncertainty::MonteCarloMoments<Poses>& mc) {
  CalibrationCovariance out;
  out.method = CovarianceMethod::kMonteCarlo;
  out.covariance = mc.covariance;
  out.solves = mc.samples + mc.failures;
  out.samples = mc.samples;
  out.failures = mc.failures;
  out.first_failure = mc.first_failure;
  out.sd_std_error = mc.sd_std_error;
  return out;
}

std::string FailedSamplesWarning(const CalibrationCovariance& covariance) {
  if (covariance.failures == 0) return {};
  return std::to_string(covariance.failures) + " of " +
         std::to_string(covariance.failures + covariance.samples) +
         " Monte Carlo samples failed to solve and are left out of the covariance (first: " +
         covariance.first_failure + ")";
}

StationNoise StationNoise::Uniform(size_t stations, const PoseSigma& robot,
                                   const PoseSigma& camera) {
  return {std::vector<Matrix6d>(stations, PoseCovariance(robot)),
          std::vector<Matrix6d>(stations, PoseCovariance(camera))};
}

handeye::Solution Resolve(const handeye::Problem& problem, const CalibrationResult& result,
                          const CalibrateOptions& options, const std::vector<bool>& kept) {
  const std::vector<handeye::Solution> start = {{result.X, result.Z}};
  switch (result.method) {
    case Method::kMl: {
      MlOptions ml;
      ml.robot_sigma = result.robot_sigma;
      ml.camera_sigma = result.camera_sigma;
      ml.camera_excess = result.camera_excess;
      ml.robust_loss = options.robust_loss;
      ml.robust_scale = options.robust_scale;
      ml.fixed = result.fixed;
      for (size_t i = 0; i < result.station_scale.size(); ++i)
        if (kept.empty() || kept[i]) ml.station_scale.push_back(result.station_scale[i]);
      return RefineMlFromGoodStart(problem, start.front(), ml);
    }
    case Method::kStrobl: {
      const StroblResult refined = RefineStrobl(problem, start);
      return {refined.X, refined.Z};
    }
    default:
      return handeye::SolveClosedForm(*Info(result.method).closed_form, problem);
  }
}

std::optional<CalibrationCovariance> PropagateCovariance(const handeye::Problem& problem,
                                                         const CalibrationResult& result,
                                                         const CalibrateOptions& calibrate_options,
                                                         const StationNoise& noise,
                                                         const CovarianceOptions& options) {
  const CovarianceMethod method =
      options.method.value_or(DefaultCovarianceMethod(result.method, problem.A.size()));
  if (method == CovarianceMethod::kNone) return std::nullopt;
  if (noise.robot.size() != problem.A.size() || noise.camera.size() != problem.B.size()) {
    throw std::invalid_argument(
        "PropagateCovariance: one robot and one camera covariance per "
        "station");
  }
  CalibrationCovariance out;
  out.method = method;
  if (method == CovarianceMethod::kInformation) {
    out.covariance =
        FirstOrderBound(problem, result.X, result.Z, noise.robot, noise.camera).covariance;
    return out;
  }
  CheckCovarianceFits(method, result.method, problem.A.size());
  const Poses stations = StackStations(problem);
  const Eigen::MatrixXd input = InputCovariance(noise);
  auto solve = [&](const Poses& perturbed) -> Poses {
    const handeye::Solution solution =
        Resolve(UnstackStations(problem, perturbed), result, calibrate_options);
    return {solution.X, solution.Z};
  };
  if (method == CovarianceMethod::kMonteCarlo) {
    uncertainty::MonteCarloOptions mc;
    mc.samples = options.samples;
    mc.seed = options.seed;
    mc.threads = options.threads;
    out =
        FromMonteCarlo(uncertainty::MonteCarloTransform<Poses, Poses>(solve, stations, input, mc));
    ++out.solves;  // the reference solve at the data
    return out;
  }
  uncertainty::Moments<Poses> moments;
  if (method == CovarianceMethod::kUnscented) {
    moments = uncertainty::UnscentedTransform<Poses, Poses>(solve, stations, input,
                                                            options.unscented, options.threads);
  } else {
    uncertainty::FirstOrderOptions linear;
    linear.threads = options.threads;
    moments = uncertainty::FirstOrderTransform<Poses, Poses>(solve, stations, input, linear);
  }
  out.covariance = moments.covariance;
  out.solves = moments.evaluations;
  return out;
}

}  // namespace hecal::estimation
