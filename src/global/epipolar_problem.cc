#include "hecal/global/epipolar_problem.h"

#include <algorithm>
#include <cmath>

namespace hecal::global {

Pose HandPose(handeye::Setup setup, const Pose& T_base_gripper) {
  return setup == handeye::Setup::kEyeInHand ? T_base_gripper : T_base_gripper.inverse();
}

Pose CameraMotion(const Pose& X, const Pose& hand_motion) {
  return X.inverse() * hand_motion * X;
}

double CheiralRayError(const Eigen::Vector3d& first, const Eigen::Vector3d& second_rotated,
                       const Eigen::Vector3d& baseline) {
  const double length = baseline.norm();
  if (length == 0.0) return 0.0;
  const Eigen::Vector3d w = baseline / length;
  const Eigen::Vector3d a = first.normalized();
  const Eigen::Vector3d c = -second_rotated.normalized();
  // sin E = max over unit q with q·w ≥ 0 of min(−q·a, −q·c). The super-level sets of the
  // objective on the sphere are intersections of two caps (geodesically convex), so the maximum
  // is the unconstrained one, −(a + c)/|a + c|, when that lies in the half-sphere, and otherwise
  // lies on the circle q ⊥ w: where the two terms cross or where one of them peaks.
  auto value = [&](const Eigen::Vector3d& q) { return std::min(-q.dot(a), -q.dot(c)); };
  double best = 0.0;
  const Eigen::Vector3d sum = a + c;
  if (sum.norm() > 1e-15 && -sum.dot(w) >= 0.0) {
    best = value(-sum.normalized());
  } else {
    std::vector<Eigen::Vector3d> candidates;
    const Eigen::Vector3d cross = w.cross(a - c);
    if (cross.norm() > 1e-15) {
      candidates.push_back(cross.normalized());
      candidates.push_back(-cross.normalized());
    }
    for (const Eigen::Vector3d& x : {a, c}) {
      const Eigen::Vector3d off = x - x.dot(w) * w;
      if (off.norm() > 1e-15) candidates.push_back(-off.normalized());
    }
    for (const Eigen::Vector3d& q : candidates) best = std::max(best, value(q));
  }
  return std::asin(std::clamp(best, 0.0, 1.0));
}

double PlaneAngle(const Eigen::Vector3d& first, const Eigen::Vector3d& second_rotated,
                  const Eigen::Vector3d& baseline) {
  const Eigen::Vector3d normal = first.cross(second_rotated);
  const double scale = normal.norm() * baseline.norm();
  if (scale == 0.0) return 0.0;
  return std::asin(std::clamp(std::abs(normal.dot(baseline)) / scale, 0.0, 1.0));
}

namespace {

template <typename PairError>
double MaxOver(const EpipolarProblem& problem, const Pose& X, PairError error) {
  double worst = 0.0;
  for (const EpipolarMotion& motion : problem.motions) {
    const Pose A = CameraMotion(X, motion.hand);
    for (const BearingPair& pair : motion.pairs) {
      worst = std::max(worst, error(pair.first, A.linear() * pair.second, A.translation()));
    }
  }
  return worst;
}

}  // namespace

std::vector<std::vector<double>> RayErrors(const EpipolarProblem& problem, const Pose& X) {
  std::vector<std::vector<double>> errors;
  for (const EpipolarMotion& motion : problem.motions) {
    const Pose A = CameraMotion(X, motion.hand);
    std::vector<double>& row = errors.emplace_back();
    for (const BearingPair& pair : motion.pairs) {
      row.push_back(CheiralRayError(pair.first, A.linear() * pair.second, A.translation()));
    }
  }
  return errors;
}

double MaxRayError(const EpipolarProblem& problem, const Pose& X) {
  return MaxOver(problem, X, CheiralRayError);
}

double MaxPlaneAngle(const EpipolarProblem& problem, const Pose& X) {
  return MaxOver(problem, X, PlaneAngle);
}

int PairCount(const EpipolarProblem& problem) {
  int count = 0;
  for (const EpipolarMotion& motion : problem.motions) count += int(motion.pairs.size());
  return count;
}

}  // namespace hecal::global
