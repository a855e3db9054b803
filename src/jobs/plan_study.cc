// The planning study (plan_study.h).
#include "hecal/jobs/plan_study.h"

#include <cmath>
#include <random>
#include <vector>

#include "hecal/core/random_draws.h"
#include "hecal/estimation/bound.h"
#include "hecal/estimation/calibrate.h"
#include "hecal/geometry/se3.h"
#include "hecal/plan/station_design.h"
#include "hecal/sim/noise.h"
#include "hecal/sim/thesis_protocol.h"

namespace hecal::jobs {
namespace {

// Sums of squares over the trials.
struct Sums {
  double predicted_rotation = 0.0, predicted_translation = 0.0;
  double achieved_rotation = 0.0, achieved_translation = 0.0;
};

void Add(const handeye::Problem& truth, const handeye::Problem& measured, const Pose& X,
         const Pose& Z, const PlanStudyOptions& options, Sums* sums) {
  const estimation::AccuracyBound bound =
      estimation::FirstOrderBound(truth, X, Z, options.robot_sigma, options.camera_sigma);
  sums->predicted_rotation += bound.rotation_rmse_X * bound.rotation_rmse_X;
  sums->predicted_translation += bound.translation_rmse_X * bound.translation_rmse_X;
  estimation::CalibrateOptions calibrate;
  calibrate.robot_sigma = options.robot_sigma;
  calibrate.camera_sigma = options.camera_sigma;
  calibrate.reject_outliers = false;
  calibrate.model_check = false;
  // The bound and the plan's criterion (plan/station_design.h) take the target's size as known:
  // the study measures them on that model (docs/plan.md), the simulated board being exact.
  calibrate.target_scale = estimation::TargetScaleMode::kStated;
  const estimation::CalibrationResult result = estimation::Calibrate(measured, calibrate);
  sums->achieved_rotation += std::pow(se3::Log(X.inverse() * result.X).head<3>().norm(), 2);
  sums->achieved_translation += (result.X.translation() - X.translation()).squaredNorm();
}

PlanStudyArm Rms(const Sums& sums, int trials) {
  const double n = static_cast<double>(trials);
  return {std::sqrt(sums.predicted_rotation / n), std::sqrt(sums.predicted_translation / n),
          std::sqrt(sums.achieved_rotation / n), std::sqrt(sums.achieved_translation / n)};
}

}  // namespace

PlanStudyRow RunPlanStudy(const PlanStudyOptions& options) {
  sim::ProtocolOptions protocol;
  protocol.setup = options.setup;
  std::mt19937_64 rng(options.seed);
  hecal::UniformRealDistribution tilt(-protocol.max_tilt, protocol.max_tilt);
  hecal::UniformRealDistribution spin(-M_PI, M_PI);
  hecal::UniformRealDistribution cube(-0.5 * protocol.cube_side, 0.5 * protocol.cube_side);
  hecal::NormalDistribution normal;
  sim::NoiseModel robot_noise, camera_noise;
  robot_noise.rotation_sigma = options.robot_sigma.rotation;
  robot_noise.translation_sigma = options.robot_sigma.translation;
  camera_noise.rotation_sigma = options.camera_sigma.rotation;
  camera_noise.translation_sigma = options.camera_sigma.translation;
  Sums random, planned;
  for (int trial = 0; trial < options.trials; ++trial) {
    const sim::HandEyeTruth truth = sim::DrawTruth(protocol, rng);
    std::vector<plan::ViewCandidate> pool;
    for (int k = 0; k < options.pool; ++k) {
      // One draw at a time, last argument first (the order of the study's first generation).
      const double offset_z = cube(rng);
      const double offset_y = cube(rng);
      const double offset_x = cube(rng);
      const double roll = spin(rng);
      const double tilt_b = tilt(rng);
      const double tilt_a = tilt(rng);
      const Pose T_target_camera =
          sim::CameraInTarget(protocol, tilt_a, tilt_b, roll, {offset_x, offset_y, offset_z});
      pool.push_back(
          {sim::RobotPoseFor(options.setup, truth, T_target_camera), T_target_camera.inverse()});
    }
    // The nominal: the truth moved by the nominal error along a random direction.
    const double dz = normal(rng);
    const double dy = normal(rng);
    const double dx = normal(rng);
    Eigen::Vector3d direction(dx, dy, dz);
    direction.normalize();
    Vector6d xi;
    xi << options.nominal_rotation_error * direction, options.nominal_translation_error * direction;
    const plan::Scene nominal{options.setup, truth.X * se3::Exp(xi), truth.Z};
    std::vector<plan::Scene> scenes = {nominal};
    for (double sign : {1.0, -1.0}) {
      plan::Scene moved = nominal;
      moved.X = nominal.X * se3::Exp(sign * xi);
      scenes.push_back(moved);
    }
    // The existing stations (the first of the pool) are the base; the rest are the candidates.
    const std::vector<plan::ViewCandidate> existing(pool.begin(), pool.begin() + options.existing);
    const std::vector<plan::ViewCandidate> rest(pool.begin() + options.existing, pool.end());
    std::vector<plan::Matrix12d> base(scenes.size(), plan::Matrix12d::Zero());
    for (const auto& station :
         plan::CandidateInformation(existing, scenes, options.robot_sigma, options.camera_sigma)) {
      for (size_t k = 0; k < scenes.size(); ++k) base[k] += station[k];
    }
    const std::vector<int> chosen = plan::ChooseStations(
        plan::CandidateInformation(rest, scenes, options.robot_sigma, options.camera_sigma), base,
        options.stations);
    for (bool is_planned : {false, true}) {
      std::vector<Pose> robot_true, camera_true, robot, camera;
      for (int k = 0; k < options.existing + options.stations; ++k) {
        const bool added = k >= options.existing;
        const size_t index =
            is_planned && added
                ? static_cast<size_t>(options.existing +
                                      chosen[static_cast<size_t>(k - options.existing)])
                : static_cast<size_t>(k);
        const plan::ViewCandidate& station = pool[index];
        robot_true.push_back(station.T_base_gripper);
        camera_true.push_back(station.T_camera_target);
        robot.push_back(sim::AddNoise(station.T_base_gripper, robot_noise, rng));
        camera.push_back(sim::AddNoise(station.T_camera_target, camera_noise, rng));
      }
      Add(handeye::MakeProblem(options.setup, robot_true, camera_true),
          handeye::MakeProblem(options.setup, robot, camera), truth.X, truth.Z, options,
          is_planned ? &planned : &random);
    }
  }
  return {Rms(random, options.trials), Rms(planned, options.trials)};
}

}  // namespace hecal::jobs
