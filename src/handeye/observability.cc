// Degeneracy checks (observability.h), O(n) in the number of stations except for the early-exit
// pure-translation scan.
//
// The motions are A_ij = A_j⁻¹ A_i (motion.h) with rotations R_ij = R_jᵀ R_i (R_i the rotation
// of A_i). What the translation of X sees of them is the normal matrix of the translation step
// (translation.cc)
//        N = Σ_{i<j} (2I − R_ij − R_ijᵀ) = Σ_{i<j} 4 sin²(θ_ij/2) (I − n_ij n_ijᵀ),
// and because Σ_{i≠j} R_jᵀ R_i = MᵀM − n I with M = Σ_i R_i, the sum over all pairs is
//        N = n² I − MᵀM                                                            (O1)
// — no pair loop. The weighted scatter of the rotation axes is S = Σ w n nᵀ = W I − N with
// w = 4 sin²(θ/2) and W = Σ w = tr(N) / 2; its eigenvalues s₁ ≥ s₂ ≥ s₃ measure how the axes
// spread: for two equally weighted axes an angle φ apart, s₂/s₁ = tan²(φ/2), so
//        spread = 2 atan √(s₂/s₁)                                                   (O2)
// is that angle, is 0 exactly when every axis is parallel, and is dominated by the large
// rotations — the ones whose axes are well defined. It is dimensionless (no length enters) and
// unaffected by station pairs that only translate, so data sets mixing pure translations and
// small rotations (tabb-rwhe-dataset1: 0–14°) or wide rotations (moveit-calibration: up to 175°)
// pass.
#include "hecal/handeye/observability.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>

#include "hecal/core/error.h"
#include "hecal/handeye/planar.h"

namespace hecal::handeye {
namespace {

std::string Degrees(double radians) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.3g deg", radians * 180.0 / std::numbers::pi);
  return text;
}

std::string Direction(const Eigen::Vector3d& v) {
  char text[64];
  std::snprintf(text, sizeof(text), "(%.3f, %.3f, %.3f)", v.x(), v.y(), v.z());
  return text;
}

// The frame in which X's translation is expressed: X = T_gripper_camera or T_base_camera.
const char* TranslationFrame(Setup setup) {
  return setup == Setup::kEyeInHand ? "gripper" : "robot base";
}

// True when some pair of stations differs in rotation by at least kMinRotation. Uses
// ‖R_i − R_j‖_F² = 8 sin²(θ_ij/2), exact for small angles; stops at the first such pair.
bool AnyRotation(const std::vector<Pose>& A) {
  const double threshold = 8.0 * std::pow(std::sin(0.5 * kMinRotation), 2);
  for (size_t i = 0; i < A.size(); ++i) {
    for (size_t j = i + 1; j < A.size(); ++j) {
      if ((A[i].linear() - A[j].linear()).squaredNorm() >= threshold) return true;
    }
  }
  return false;
}

// What to do about an unobservable direction: tilt, or give the component (planar.h).
std::string AxesFix(const Eigen::Vector3d& direction) {
  return "rotate the robot about at least two clearly different axes (tilt as well as spin); "
         "for a planar robot give that component with --fix " +
         ComponentName(NearestAxis(direction)) + "=VALUE (method ml)";
}

}  // namespace

Eigen::Matrix3d TranslationNormalMatrix(const std::vector<Pose>& A) {
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
  for (const Pose& pose : A) M += pose.linear();
  const double n = static_cast<double>(A.size());
  return n * n * Eigen::Matrix3d::Identity() - M.transpose() * M;
}

void CheckObservability(const Problem& problem, bool translation_fixed) {
  if (problem.A.size() != problem.B.size()) {
    throw std::invalid_argument("CheckObservability: " + std::to_string(problem.A.size()) +
                                " robot poses but " + std::to_string(problem.B.size()) +
                                " camera poses");
  }
  const int n = static_cast<int>(problem.A.size());
  if (n < 3) {
    throw DegenerateError(
        "the hand-eye transform from " + std::to_string(n) +
            " station(s): at least 3 are needed, so that two motions can rotate about different "
            "axes",
        "record more stations (10-20 with varied orientations are recommended)");
  }
  if (!AnyRotation(problem.A)) {
    throw DegenerateError(
        "the translation of X (" + std::string(XFrameName(problem.setup)) +
            "): the robot only translates between stations (every relative rotation is below " +
            Degrees(kMinRotation) + ")",
        "rotate the robot between stations, about at least two different axes");
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(TranslationNormalMatrix(problem.A));
  const Eigen::Vector3d& lambda = eigen.eigenvalues();  // ascending
  const double W = 0.5 * lambda.sum();
  const double s1 = std::max(W - lambda(0), 0.0);
  const double s2 = std::max(W - lambda(1), 0.0);
  const double spread = 2.0 * std::atan2(std::sqrt(s2), std::sqrt(s1));  // (O2)
  if (spread < kParallelAxes && !translation_fixed) {
    throw DegenerateError(
        "the translation of X (" + std::string(XFrameName(problem.setup)) +
            ") along the common rotation axis " + Direction(eigen.eigenvectors().col(0)) +
            " of the " + TranslationFrame(problem.setup) +
            " frame: every relative rotation of the robot is about parallel axes (spread " +
            Degrees(spread) + ")",
        AxesFix(eigen.eigenvectors().col(0)));
  }
}

std::string CheckObservabilityUnderNoise(const Problem& problem, double robot_rotation_sigma,
                                         bool translation_fixed) {
  const double pairs = 0.5 * static_cast<double>(problem.A.size() * (problem.A.size() - 1));
  const double floor = pairs * 4.0 * robot_rotation_sigma * robot_rotation_sigma;
  if (!(floor > 0.0)) return {};
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(TranslationNormalMatrix(problem.A));
  const Eigen::Vector3d rho = eigen.eigenvalues() / floor;  // ascending
  const std::string x = "the translation of X (" + std::string(XFrameName(problem.setup)) + ")";
  const std::string noise = "the robot rotation noise (" + Degrees(robot_rotation_sigma) + ")";
  char ratio[64];
  std::snprintf(ratio, sizeof(ratio), "%.3g times", rho(0));
  if (rho(2) < kNoiseDegenerate) {
    throw DegenerateError(
        x + ": the robot's rotations between stations are within " + noise +
            ", so it effectively only translates",
        "rotate the robot between stations by tens of degrees, about at least two different "
        "axes");
  }
  // With one component given (planar.h) the least observed direction is not estimated.
  const int weakest = translation_fixed ? 1 : 0;
  const std::string along = " along " + Direction(eigen.eigenvectors().col(weakest)) +
                            " of the " + TranslationFrame(problem.setup) + " frame";
  std::snprintf(ratio, sizeof(ratio), "%.3g times", rho(weakest));
  if (rho(weakest) < kNoiseDegenerate) {
    throw DegenerateError(x + along + ": the robot's rotation axes differ only by " + noise +
                              " (the axes' spread observes it " + ratio +
                              " what noise alone would)",
                          translation_fixed ? "rotate the robot by tens of degrees about its axis "
                                              "and move it across the axis between stations"
                                            : AxesFix(eigen.eigenvectors().col(0)));
  }
  if (rho(weakest) < kNoiseWeak) {
    return x + along + " is weakly observed: the rotation axes' spread observes it only " + ratio +
           " what " + noise +
           " alone would; tilt the robot about more different axes to pin it down";
  }
  return {};
}

}  // namespace hecal::handeye
