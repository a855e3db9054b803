// Candidate stations for `hecal plan` (view_candidates.h).
#include "hecal/plan/view_candidates.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "hecal/core/random_draws.h"
#include "hecal/sim/thesis_protocol.h"

namespace hecal::plan {
namespace {

// Centre and largest extent of the target's points.
void Extent(const std::vector<pose::ObjectPoint>& target, Eigen::Vector3d* centre, double* size) {
  Eigen::Vector3d low = Eigen::Vector3d::Constant(1e300), high = -low;
  for (const pose::ObjectPoint& point : target) {
    low = low.cwiseMin(point.position);
    high = high.cwiseMax(point.position);
  }
  *centre = 0.5 * (low + high);
  *size = (high - low).maxCoeff();
}

// A rotation whose z column is `axis` (unit), spun by `spin` about it.
Eigen::Matrix3d LookAlong(const Eigen::Vector3d& axis, double spin) {
  const Eigen::Vector3d helper =
      std::abs(axis.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d x0 = axis.cross(helper).normalized();
  const Eigen::Vector3d y0 = axis.cross(x0);
  Eigen::Matrix3d R;
  R.col(0) = std::cos(spin) * x0 + std::sin(spin) * y0;
  R.col(1) = axis.cross(R.col(0));
  R.col(2) = axis;
  return R;
}

}  // namespace

double DefaultDistance(const pose::CameraModel& camera,
                       const std::vector<pose::ObjectPoint>& target) {
  Eigen::Vector3d centre;
  double size = 0.0;
  Extent(target, &centre, &size);
  return camera.fx * size / (0.5 * camera.width);
}

bool TargetInView(const pose::CameraModel& camera, const std::vector<pose::ObjectPoint>& target,
                  const Pose& T_camera_target, double margin_pixels) {
  for (const pose::ObjectPoint& point : target) {
    const Eigen::Vector3d p = T_camera_target * point.position;
    if (!(p.z() > 0.0)) return false;
    const Eigen::Vector2d pixel = pose::Project(camera, p);
    if (!(pixel.x() >= margin_pixels && pixel.x() <= camera.width - margin_pixels &&
          pixel.y() >= margin_pixels && pixel.y() <= camera.height - margin_pixels)) {
      return false;
    }
  }
  return true;
}

std::vector<ViewCandidate> ViewCandidates(const std::vector<Scene>& scenes,
                                          const pose::CameraModel& camera,
                                          const std::vector<pose::ObjectPoint>& target,
                                          const io::Workspace& workspace,
                                          const ViewOptions& options, std::mt19937_64& rng,
                                          int* samples) {
  Eigen::Vector3d centre;
  double size = 0.0;
  Extent(target, &centre, &size);
  const double distance =
      options.distance > 0.0 ? options.distance : DefaultDistance(camera, target);
  const double margin = options.margin_fraction * camera.width;
  hecal::UniformRealDistribution unit(0.0, 1.0);
  hecal::UniformRealDistribution spin(-std::numbers::pi, std::numbers::pi);
  hecal::UniformRealDistribution aim(-0.25 * size, 0.25 * size);
  hecal::UniformRealDistribution range(0.8 * distance, 1.2 * distance);
  const double cap = 1.0 - std::cos(options.max_board_tilt);
  std::vector<ViewCandidate> kept;
  int sample = 0;
  for (; sample < options.max_samples && static_cast<int>(kept.size()) < options.candidates;
       ++sample) {
    // Uniform on the cap about −z: cos θ uniform in [cos max, 1].
    const double cos_theta = 1.0 - cap * unit(rng);
    const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
    const double phi = spin(rng);
    const Eigen::Vector3d direction(sin_theta * std::cos(phi), sin_theta * std::sin(phi),
                                    -cos_theta);
    const Eigen::Vector3d position = centre + range(rng) * direction;
    const double aim_y = aim(rng);  // drawn before x: the order of the first generation
    const double aim_x = aim(rng);
    const Eigen::Vector3d aim_point = centre + Eigen::Vector3d(aim_x, aim_y, 0.0);
    const Pose T_target_camera =
        MakePose(LookAlong((aim_point - position).normalized(), spin(rng)), position);
    const Pose T_camera_target = T_target_camera.inverse();
    bool ok = true;
    ViewCandidate candidate;
    for (size_t k = 0; k < scenes.size() && ok; ++k) {
      const Scene& scene = scenes[k];
      // The robot pose is planned at the nominal (k = 0); a perturbed nominal sees it from there.
      if (k == 0) {
        candidate.T_base_gripper =
            sim::RobotPoseFor(scene.setup, {scene.X, scene.Z}, T_target_camera);
        candidate.T_camera_target = T_camera_target;
        ok = workspace.Contains(candidate.T_base_gripper);
      }
      if (!ok) break;
      const Pose A = scene.setup == handeye::Setup::kEyeInHand ? candidate.T_base_gripper
                                                               : candidate.T_base_gripper.inverse();
      ok = TargetInView(camera, target, (A * scene.X).inverse() * scene.Z, margin);
    }
    if (ok) kept.push_back(candidate);
  }
  if (samples != nullptr) *samples = sample;
  return kept;
}

}  // namespace hecal::plan
