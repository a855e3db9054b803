#include "hecal/estimation/station_selection.h"

#include <algorithm>
#include <cmath>

#include "hecal/core/options_check.h"
#include "hecal/estimation/initialization.h"
#include "hecal/estimation/ml.h"
#include "hecal/handeye/observability.h"

namespace hecal::estimation {
namespace {

constexpr int kMaxRounds = 5;

int CountUnused(const std::vector<bool>& used) {
  return static_cast<int>(std::count(used.begin(), used.end(), false));
}

// The stations' camera noise replaced by their own covariances (unit weight on the camera
// rotation component, none on the camera translation component), and the robot noise of the
// candidate set estimated next to them unless given.
NoiseVariances WithCameraCovariances(const StationSelectionOptions& options,
                                     const std::vector<bool>& candidate, double length_scale,
                                     std::vector<StationLinearization>* stations) {
  std::vector<StationLinearization> set;
  for (size_t i = 0; i < stations->size(); ++i) {
    StationLinearization& station = (*stations)[i];
    station.components[kCameraRotation] = options.camera_covariances.at(i);
    station.components[kCameraTranslation].setZero();
    if (candidate[i]) set.push_back(station);
  }
  NoiseSpec spec;
  spec.variances[kCameraRotation] = 1.0;
  spec.variances[kCameraTranslation] = 0.0;
  if (options.robot_sigma) {
    spec.variances[kRobotRotation] = options.robot_sigma->rotation * options.robot_sigma->rotation;
    spec.variances[kRobotTranslation] =
        options.robot_sigma->translation * options.robot_sigma->translation;
    return spec.variances;
  }
  spec.group = {0, 1, -1, -1, -1, -1};
  return EstimateNoise(set, spec, length_scale).variances;
}

}  // namespace

std::vector<int> StationSelection::Rejected() const {
  std::vector<int> rejected;
  for (size_t i = 0; i < used.size(); ++i)
    if (!used[i]) rejected.push_back(static_cast<int>(i));
  return rejected;
}

StationSelection AllStations(size_t n) {
  StationSelection selection;
  selection.used.assign(n, true);
  return selection;
}

bool StationSelectionOptions::IsValid(std::string* why) const {
  if (!SigmaIsValid(robot_sigma, "StationSelectionOptions.robot_sigma", why) ||
      !SigmaIsValid(camera_sigma, "StationSelectionOptions.camera_sigma", why)) {
    return false;
  }
  for (const Matrix6d& covariance : camera_covariances) {
    if (!covariance.allFinite()) {
      return Invalid(why, "StationSelectionOptions.camera_covariances",
                     "a camera pose covariance is not finite",
                     "give finite PnP covariances, or none to estimate the camera noise");
    }
  }
  return consensus.IsValid(why);
}

StationSelection SelectStations(const handeye::Problem& problem,
                                const StationSelectionOptions& options) {
  RequireValid(options);
  const size_t n = problem.A.size();
  if (n < 3) handeye::CheckObservability(problem, options.fix.has_value());  // throws: too few
  StationSelection selection = AllStations(n);
  const int max_rejected = static_cast<int>((n - 3) / 2);
  if (max_rejected == 0) return selection;

  if (!options.fix) selection.consensus = handeye::FindStationConsensus(problem, options.consensus);
  std::vector<bool> candidate =
      options.fix ? std::vector<bool>(n, true) : selection.consensus.inlier;
  // A consensus that leaves out more than may be rejected is no basis: test from all stations.
  if (CountUnused(candidate) > max_rejected) candidate.assign(n, true);

  // The level per data set (header): α per station from 1 − (1 − α)ⁿ = kFalseRejection; F
  // instead of χ² when the noise is estimated from the candidate set.
  StationTestOptions test_options;
  test_options.false_alarm = -std::expm1(std::log1p(-kFalseRejection) / static_cast<double>(n));
  test_options.estimated = options.camera_covariances.empty()
                               ? !(options.robot_sigma && options.camera_sigma)
                               : !options.robot_sigma;
  MlOptions ml_options;
  ml_options.robot_sigma = options.robot_sigma;
  ml_options.camera_sigma = options.camera_sigma;
  ml_options.heavy_tails = false;  // the test is Gaussian (header)
  std::vector<handeye::Solution> starts;
  for (int round = 0; round < kMaxRounds; ++round) {
    const handeye::Problem set = handeye::SubProblem(problem, candidate);
    handeye::CheckObservability(set, options.fix.has_value());
    if (options.fix) ml_options.fixed = handeye::ResolveFix(set, *options.fix);
    // Later rounds change the set by a few stations: the last fit is in the right basin.
    if (round == 0) {
      starts = options.fix
                   ? std::vector<handeye::Solution>{handeye::FixedStart(set, *ml_options.fixed)}
                   : StartingSolutions(set);
    }
    const MlResult fit = RefineMl(set, starts, ml_options);
    starts = {{fit.X, fit.Z}};
    std::vector<StationLinearization> stations = LinearizeStations(problem, fit.X, fit.Z);
    NoiseVariances variances = fit.noise.variances;
    if (!options.camera_covariances.empty()) {
      variances = WithCameraCovariances(options, candidate, handeye::LengthScale(set), &stations);
    }
    selection.tests = TestStations(stations, candidate, variances, test_options);
    selection.used = candidate;
    selection.rounds = round + 1;
    std::vector<bool> next(n);
    for (size_t i = 0; i < n; ++i) next[i] = !selection.tests[i].outlier;
    selection.flagged = CountUnused(next);
    if (selection.flagged > max_rejected) {
      selection.too_many = true;
      selection.used.assign(n, true);
      return selection;
    }
    if (next == candidate) {
      if (round == 0) {
        selection.fit = fit;
        selection.fit_robot_sigma = options.robot_sigma;
        selection.fit_camera_sigma = options.camera_sigma;
      }
      break;
    }
    candidate = next;
  }
  return selection;
}

std::vector<int> TrueIndices(const std::vector<bool>& flags) {
  std::vector<int> indices;
  for (size_t i = 0; i < flags.size(); ++i)
    if (flags[i]) indices.push_back(static_cast<int>(i));
  return indices;
}

}  // namespace hecal::estimation
