// OpenCV's hand–eye functions as hecal jobs: see opencv_drop_in.h.
#include "hecal/jobs/opencv_drop_in.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "hecal/core/error.h"
#include "hecal/estimation/calibrate.h"
#include "hecal/estimation/initialization.h"
#include "hecal/estimation/ml.h"
#include "hecal/geometry/nearest_rotation.h"
#include "hecal/geometry/se3.h"
#include "hecal/geometry/so3.h"
#include "hecal/handeye/closed_form.h"
#include "hecal/handeye/observability.h"
#include "hecal/handeye/problem.h"

namespace hecal::jobs {
namespace {

// A matrix within this of a rotation is projected to the nearest one (6-digit text, float32), as
// the pose files' reader does (io/pose_table.h); beyond it refused.
constexpr double kRotationTolerance = 1e-3;
constexpr double kProjectAbove = 1e-12;      // float32 input: project to the nearest rotation

std::string MethodList(bool robot_world) {
  return robot_world ? "CALIB_ROBOT_WORLD_HAND_EYE_SHAH (0), CALIB_ROBOT_WORLD_HAND_EYE_LI (1) or "
                       "CALIB_HAND_EYE_ML (" + std::to_string(kDropInMl) + ")"
                     : "CALIB_HAND_EYE_TSAI (0), _PARK (1), _HORAUD (2), _ANDREFF (3), "
                       "_DANIILIDIS (4) or CALIB_HAND_EYE_ML (" + std::to_string(kDropInMl) + ")";
}

// The poses of one OpenCV argument pair, checked, as T (rotation, translation).
std::vector<Pose> ToPoses(const DropInPoses& poses) {
  if (poses.R.size() != poses.t.size()) {
    throw InputError(poses.t_name, 0,
                     "has " + std::to_string(poses.t.size()) + " translations but " + poses.R_name +
                         " has " + std::to_string(poses.R.size()) + " rotations",
                     "give one rotation and one translation per pose");
  }
  std::vector<Pose> out(poses.R.size());
  for (size_t i = 0; i < poses.R.size(); ++i) {
    const DropInRotation& rotation = poses.R[i];
    const std::string at = "entry " + std::to_string(i);
    if (!(rotation.is_vector ? rotation.vector.allFinite() : rotation.matrix.allFinite())) {
      throw InputError(poses.R_name, 0, at + " is not finite (NaN or infinity)",
                       "remove that pose or fix the value");
    }
    if (!poses.t[i].allFinite()) {
      throw InputError(poses.t_name, 0, at + " is not finite (NaN or infinity)",
                       "remove that pose or fix the value");
    }
    Eigen::Matrix3d R;
    if (rotation.is_vector) {
      R = so3::Exp(rotation.vector);
    } else {
      R = rotation.matrix;
      const double error = so3::OrthonormalityError(R);
      if (error > kRotationTolerance || R.determinant() <= 0.0) {
        throw InputError(poses.R_name, 0,
                         at + " is not a rotation matrix (|RᵀR − I| or |det R − 1| is " +
                             std::to_string(error) + ", det R = " +
                             std::to_string(R.determinant()) + ")",
                         "give 3×3 rotation matrices (orthonormal, det +1) or Rodrigues vectors");
      }
      if (error > kProjectAbove) R = NearestRotationSvd(R);
    }
    out[i].linear() = R;
    out[i].translation() = poses.t[i];
  }
  return out;
}

estimation::Method RequireMethod(int method, bool robot_world) {
  const std::optional<estimation::Method> found = DropInMethod(method, robot_world);
  if (!found) {
    throw InputError("method", 0,
                     "unknown method " + std::to_string(method) +
                         " (OpenCV 4.6 would return the identity without a word)",
                     "use " + MethodList(robot_world));
  }
  return *found;
}

void RequireLengths(const DropInPoses& robot, const DropInPoses& camera,
                    const std::vector<Pose>& a, const std::vector<Pose>& b) {
  if (a.size() != b.size()) {
    throw InputError(camera.R_name, 0,
                     "has " + std::to_string(b.size()) + " poses but " + robot.R_name + " has " +
                         std::to_string(a.size()),
                     "give one pose of each list per station, in the same order");
  }
  if (a.size() < 3) {
    throw InputError(robot.R_name, 0,
                     "has " + std::to_string(a.size()) +
                         " poses; hand–eye calibration needs at least 3 (two motions about "
                         "non-parallel axes)",
                     "record more stations (10 or more, with rotations about different axes)");
  }
}

// The plug-in noise model of the drop-in's ml: the RMS per axis of the residuals
// r_i = Log(Z⁻¹ A_i X B_i) at `start`, split equally between robot and camera (floored at 1e-9 rad
// and 1e-9·L, so that noise-free data keep a valid model).
estimation::PoseSigma PlugInSigma(const handeye::Problem& problem, const handeye::Solution& start) {
  double rotation = 0.0, translation = 0.0;
  for (size_t i = 0; i < problem.A.size(); ++i) {
    const Vector6d r = se3::Log(start.Z.inverse() * problem.A[i] * start.X * problem.B[i]);
    rotation += r.head<3>().squaredNorm();
    translation += r.tail<3>().squaredNorm();
  }
  const double components = 6.0 * static_cast<double>(problem.A.size());  // 3 axes × 2 sources
  return {std::max(std::sqrt(rotation / components), 1e-9),
          std::max(std::sqrt(translation / components), 1e-9 * handeye::LengthScale(problem))};
}

// X and Z by `method` on every station (DropInCalibrateOptions::reject_outliers false):
//   closed forms: the observability check and the solver, as estimation::Calibrate runs them
//     (the residuals, noise estimate and warnings Calibrate adds are not part of OpenCV's answer,
//     and at 15 stations cost about 20 times the solve);
//   ml: the observability check, ml's first start (estimation::StartingSolutions: Shah's closed
//     form), then estimation::RefineMl with the plug-in noise model above as given sigmas — one
//     weighted refinement (more starts on demand, ml.h) instead of Calibrate's REML alternation
//     of pose and noise levels and its heavy-tail test, which at 15 stations take about 200
//     times as long (docs/python.md#speed).
// With reject_outliers: estimation::Calibrate (its station selection, then the method), without
// covariance and model check.
handeye::Solution Solve(const handeye::Problem& problem, estimation::Method method,
                        const DropInCalibrateOptions& options) {
  if (!options.reject_outliers) {
    const estimation::MethodInfo& info = estimation::Info(method);
    if (info.closed_form) {
      handeye::CheckObservability(problem);
      return handeye::SolveClosedForm(*info.closed_form, problem);
    }
    if (method == estimation::Method::kMl) {
      handeye::CheckObservability(problem);
      const std::vector<handeye::Solution> starts = estimation::StartingSolutions(problem);
      estimation::MlOptions ml;
      ml.robot_sigma = ml.camera_sigma = PlugInSigma(problem, starts.front());
      const estimation::MlResult result = estimation::RefineMl(problem, starts, ml);
      return {result.X, result.Z};
    }
  }
  estimation::CalibrateOptions calibrate;
  calibrate.method = method;
  calibrate.covariance.method = estimation::CovarianceMethod::kNone;
  calibrate.model_check = false;
  calibrate.reject_outliers = options.reject_outliers;
  calibrate.covariance.threads = 1;
  const estimation::CalibrationResult result = estimation::Calibrate(problem, calibrate);
  return {result.X, result.Z};
}

DropInTransform ToTransform(const Pose& T) { return {T.linear(), T.translation()}; }

}  // namespace

std::optional<estimation::Method> DropInMethod(int method, bool robot_world) {
  using estimation::Method;
  if (method == kDropInMl) return Method::kMl;
  if (robot_world) {
    switch (method) {
      case 0: return Method::kShah;
      case 1: return Method::kLi;
      default: return std::nullopt;
    }
  }
  switch (method) {
    case 0: return Method::kTsaiLenz;
    case 1: return Method::kParkMartin;
    case 2: return Method::kHoraud;
    case 3: return Method::kAndreff;
    case 4: return Method::kDaniilidis;
    default: return std::nullopt;
  }
}

DropInTransform CalibrateHandEyeDropIn(const DropInPoses& gripper2base,
                                       const DropInPoses& target2cam,
                                       const DropInCalibrateOptions& options) {
  const estimation::Method method = RequireMethod(options.method, /*robot_world=*/false);
  const std::vector<Pose> A = ToPoses(gripper2base);
  const std::vector<Pose> B = ToPoses(target2cam);
  RequireLengths(gripper2base, target2cam, A, B);
  const handeye::Problem problem{handeye::Setup::kEyeInHand, A, B};
  return ToTransform(Solve(problem, method, options).X);
}

RobotWorldDropIn CalibrateRobotWorldHandEyeDropIn(const DropInPoses& world2cam,
                                                  const DropInPoses& base2gripper,
                                                  const DropInCalibrateOptions& options) {
  const estimation::Method method = RequireMethod(options.method, /*robot_world=*/true);
  const std::vector<Pose> B = ToPoses(world2cam);
  std::vector<Pose> A = ToPoses(base2gripper);
  RequireLengths(base2gripper, world2cam, A, B);
  for (Pose& T : A) T = T.inverse();  // T_base_gripper
  const handeye::Problem problem{handeye::Setup::kEyeInHand, A, B};
  const handeye::Solution solution = Solve(problem, method, options);
  return {ToTransform(solution.Z.inverse()), ToTransform(solution.X.inverse())};
}

}  // namespace hecal::jobs
