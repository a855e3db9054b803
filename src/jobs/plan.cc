// `hecal plan` as one job (plan.h).
#include "hecal/jobs/plan.h"

#include <cmath>
#include <numbers>
#include <random>

#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/geometry/se3.h"
#include "hecal/io/camera_file.h"
#include "hecal/io/target_file.h"
#include "hecal/io/workspace_file.h"
#include "hecal/jobs/pose_file_calibration.h"
#include "hecal/plan/station_design.h"
#include "hecal/plan/view_candidates.h"

namespace hecal::jobs {
namespace {

// Defaults for the prediction of a new plan (docs/plan.md): an industrial arm's pose repeatability
// and a PnP pose of a board about half a metre away.
constexpr estimation::PoseSigma kRobotSigma{0.05 * std::numbers::pi / 180.0, 0.1e-3};
constexpr estimation::PoseSigma kCameraSigma{0.1 * std::numbers::pi / 180.0, 0.5e-3};
constexpr int kMinCandidates = 50;  // fewer seeing the target: the plan has no choice to make

// Step 3 of plan.h: the nominal and 4 copies moved by the nominal error.
std::vector<plan::Scene> Nominals(const plan::Scene& nominal, const io::Workspace& workspace) {
  std::vector<plan::Scene> scenes = {nominal};
  const double r = workspace.nominal_rotation_error / std::sqrt(3.0);
  const double t = workspace.nominal_translation_error / std::sqrt(3.0);
  for (const Eigen::Vector3d& d : {Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(-1, -1, -1),
                                   Eigen::Vector3d(1, -1, 1), Eigen::Vector3d(-1, 1, -1)}) {
    Vector6d xi;
    xi << r * d, t * d;
    plan::Scene scene = nominal;
    scene.X = nominal.X * se3::Exp(xi);
    scene.Z = nominal.Z * se3::Exp(-xi);
    scenes.push_back(scene);
  }
  return scenes;
}

// X's largest per-axis 1σ in rotation and in translation.
bool Reaches(const Eigen::Matrix<double, 6, 6>& covariance, const estimation::PoseSigma& goal) {
  const Vector6d sigma = covariance.diagonal().cwiseMax(0.0).cwiseSqrt();
  return sigma.head<3>().maxCoeff() <= goal.rotation &&
         sigma.tail<3>().maxCoeff() <= goal.translation;
}

}  // namespace

bool PlanOptions::IsValid(std::string* why) const {
  if (stations < 1 || (existing_robot.empty() && stations < 3)) {
    return Invalid(why, "PlanOptions.stations",
                   "at least 3 stations are needed (1 to add to an existing calibration), got " +
                       std::to_string(stations),
                   "plan e.g. 10 stations");
  }
  for (const auto& [field, value] : {std::pair<const char*, const std::string*>{"PlanOptions.target", &target},
                                     {"PlanOptions.intrinsics", &intrinsics},
                                     {"PlanOptions.workspace", &workspace}}) {
    if (value->empty()) return Invalid(why, field, "no file given", "give the file");
  }
  if (!(distance >= 0.0) || !std::isfinite(distance)) {
    return Invalid(why, "PlanOptions.distance", "the distance must be positive and finite",
                   "give the camera-to-board distance in metres, or leave it out");
  }
  if (!(max_board_tilt > 0.0 && max_board_tilt <= 80.0 * std::numbers::pi / 180.0)) {
    return Invalid(why, "PlanOptions.max_board_tilt", "the board tilt must be in (0, 80] degrees",
                   "use e.g. 45 degrees");
  }
  const auto bad = [](const std::optional<estimation::PoseSigma>& sigma) {
    return sigma && !(sigma->rotation > 0.0 && sigma->translation > 0.0 &&
                      std::isfinite(sigma->rotation) && std::isfinite(sigma->translation));
  };
  if (bad(robot_sigma) || bad(camera_sigma)) {
    return Invalid(why, bad(robot_sigma) ? "PlanOptions.robot_sigma" : "PlanOptions.camera_sigma",
                   "the noise for the prediction must be positive and finite",
                   "give e.g. 0.1,0.05 (mm, degrees)");
  }
  if (existing_robot.empty() != existing_camera.empty()) {
    return Invalid(why, existing_robot.empty() ? "PlanOptions.existing_robot"
                                               : "PlanOptions.existing_camera",
                   "the existing calibration needs both its robot and its camera table",
                   "give both files");
  }
  if (bad(goal)) {
    return Invalid(why, "PlanOptions.goal", "the goal's sigmas must be positive",
                   "give e.g. 0.05deg,0.5mm");
  }
  return true;
}

PlanResult PlanStations(const PlanOptions& options) {
  RequireValid(options);
  const std::vector<pose::ObjectPoint> target = pose::ObjectPoints(io::ReadTargetFile(options.target));
  const pose::CameraModel camera = io::ReadCameraFile(options.intrinsics).camera;
  if (camera.width <= 0 || camera.height <= 0) {
    throw InputError(options.intrinsics, 0, "the camera file has no image size",
                     "add width and height (pixels): the plan keeps the target inside the image");
  }
  const io::Workspace workspace = io::ReadWorkspaceFile(options.workspace);

  PlanResult result;
  result.setup = options.setup;
  plan::Scene nominal{options.setup, Pose::Identity(), Pose::Identity()};
  std::vector<Pose> existing_robot, existing_camera;
  if (!options.existing_robot.empty()) {
    PoseFileCalibrationOptions calibration;
    calibration.robot = options.existing_robot;
    calibration.camera = options.existing_camera;
    calibration.robot_read = calibration.camera_read = options.read;
    calibration.setup = options.setup;
    calibration.calibrate.robot_sigma = options.robot_sigma;
    calibration.calibrate.camera_sigma = options.camera_sigma;
    calibration.calibrate.model_check = false;
    const report::ResultDocument document = CalibrateFromPoseFiles(calibration).document;
    const estimation::CalibrationResult& fit = document.results.front();
    nominal.X = fit.X;
    nominal.Z = fit.Z;
    result.robot_sigma = fit.robot_sigma;
    result.camera_sigma = fit.camera_sigma;
    result.nominal_from_existing = true;
    const io::Stations stations =
        io::PairStations(io::ReadPoseTable(options.existing_robot, options.read),
                         io::ReadPoseTable(options.existing_camera, options.read));
    std::vector<bool> used(stations.robot.size(), true);
    for (int i : document.rejected) used[static_cast<size_t>(i)] = false;
    for (size_t i = 0; i < stations.robot.size(); ++i) {
      if (!used[i]) continue;
      existing_robot.push_back(stations.robot[i]);
      existing_camera.push_back(stations.camera[i]);
    }
  } else {
    if (!workspace.hand_eye || !workspace.target) {
      throw InputError(options.workspace, 0,
                       std::string("the workspace file has no nominal ") +
                           (workspace.hand_eye ? "target" : "hand_eye") +
                           " pose, which a new plan needs",
                       "add hand_eye: and target: (x, y, z, qw, qx, qy, qz; docs/plan.md), or "
                       "plan from an existing calibration with --existing");
    }
    nominal.X = *workspace.hand_eye;
    nominal.Z = *workspace.target;
    result.robot_sigma = options.robot_sigma.value_or(kRobotSigma);
    result.camera_sigma = options.camera_sigma.value_or(kCameraSigma);
  }
  result.X = nominal.X;
  result.Z = nominal.Z;
  result.existing_stations = static_cast<int>(existing_robot.size());

  const std::vector<plan::Scene> scenes = Nominals(nominal, workspace);
  plan::ViewOptions view;
  view.distance = options.distance;
  view.max_board_tilt = options.max_board_tilt;
  std::mt19937_64 rng(options.seed);
  const std::vector<plan::ViewCandidate> candidates =
      plan::ViewCandidates(scenes, camera, target, workspace, view, rng, &result.samples);
  result.candidates = static_cast<int>(candidates.size());
  if (result.candidates < std::max(kMinCandidates, options.stations)) {
    throw InputError(options.workspace, 0,
                     "only " + std::to_string(result.candidates) + " of " +
                         std::to_string(result.samples) +
                         " sampled poses keep the whole target in view inside the workspace",
                     "widen the workspace box or tilt cone, check the nominal target and hand_eye "
                     "poses, or give --distance");
  }

  // The base: the existing stations' information at each nominal (zero for a new plan).
  std::vector<plan::Matrix12d> base(scenes.size(), plan::Matrix12d::Zero());
  if (!existing_robot.empty()) {
    std::vector<plan::ViewCandidate> taken;
    for (size_t i = 0; i < existing_robot.size(); ++i)
      taken.push_back({existing_robot[i], existing_camera[i]});
    const auto information =
        plan::CandidateInformation(taken, scenes, result.robot_sigma, result.camera_sigma);
    for (const auto& station : information)
      for (size_t k = 0; k < scenes.size(); ++k) base[k] += station[k];
    result.before = plan::XCovariance(base.front());
  }
  const auto information =
      plan::CandidateInformation(candidates, scenes, result.robot_sigma, result.camera_sigma);
  const std::vector<int> chosen = plan::ChooseStations(information, base, options.stations);
  plan::Matrix12d total = base.front();
  for (int c : chosen) {
    result.T_base_gripper.push_back(candidates[static_cast<size_t>(c)].T_base_gripper);
    result.T_camera_target.push_back(candidates[static_cast<size_t>(c)].T_camera_target);
    total += information[static_cast<size_t>(c)].front();
  }
  result.predicted = plan::XCovariance(total);

  if (options.goal) {
    // The fewest stations that reach it: greedy additions from the base (no exchange passes).
    const int most = std::min(result.candidates, kMaxGoalStations - result.existing_stations);
    const std::vector<int> order =
        plan::ChooseStations(information, base, most, /*exchange=*/false);
    plan::Matrix12d sum = base.front();
    for (size_t k = 0; k < order.size(); ++k) {
      sum += information[static_cast<size_t>(order[k])].front();
      const int count = result.existing_stations + static_cast<int>(k) + 1;
      if (count >= 3 && Reaches(plan::XCovariance(sum), *options.goal)) {
        result.goal_stations = count;
        break;
      }
    }
  }
  return result;
}

}  // namespace hecal::jobs
