// The parent-frame σ of a pose's translation against known answers and against sampling:
// a quarter turn about z maps the camera's x to the gripper's −y, so the per-axis σ must swap x
// and y; for a general rotation and a full covariance (rotation–translation cross terms included)
// the formula must match the covariance of the translations of right-perturbed poses
// T̂ · Exp(δ), δ ~ N(0, C), within the sampling error — and the child-frame σ must not.
#include "hecal/report/translation_sigma.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>

#include "hecal/core/random_draws.h"
#include "hecal/geometry/se3.h"

namespace hecal::report {
namespace {

TEST(TranslationSigma, ParentFrameIsTheFirstName) {
  EXPECT_EQ(ParentFrame("T_gripper_camera"), "gripper");
  EXPECT_EQ(ParentFrame("T_base_target"), "base");
  EXPECT_EQ(ParentFrame("T_base_camera"), "base");
  EXPECT_EQ(ParentFrame("T_gripper_target"), "gripper");
}

// σ (1, 2, 3) mm along the camera's x, y, z; rotation–translation cross terms that must not
// enter at first order.
Matrix6d CameraCovariance() {
  Matrix6d C = Matrix6d::Zero();
  C.diagonal() << 1e-4, 4e-4, 9e-4, 1e-6, 4e-6, 9e-6;
  C(0, 3) = C(3, 0) = 0.5 * 1e-2 * 1e-3;
  C(2, 4) = C(4, 2) = -0.7 * 3e-2 * 2e-3;
  return C;
}

TEST(TranslationSigma, QuarterTurnSwapsTheAxes) {
  // Rz(−90°): the camera's x is the gripper's −y, its y the gripper's x, z unchanged.
  Pose X = Pose::Identity();
  X.linear() << 0, 1, 0, -1, 0, 0, 0, 0, 1;
  X.translation() << 0.1, -0.2, 0.3;
  const Eigen::Matrix3d C_t = TranslationCovarianceInParent(X, CameraCovariance());
  EXPECT_NEAR(std::sqrt(C_t(0, 0)), 2e-3, 1e-15);
  EXPECT_NEAR(std::sqrt(C_t(1, 1)), 1e-3, 1e-15);
  EXPECT_NEAR(std::sqrt(C_t(2, 2)), 3e-3, 1e-15);
  EXPECT_NEAR(C_t(0, 1), 0.0, 1e-18);

  std::ostringstream text;
  text << std::fixed;
  text.precision(3);
  PrintTranslationSigmaInParent(text, "X", "T_gripper_camera", X, CameraCovariance());
  EXPECT_EQ(text.str(),
            "  1σ of X's translation along the gripper's axes: (2.000 1.000 3.000) mm\n");

  const nlohmann::json j =
      TranslationSigmaInParentJson("T_base_camera", X, CameraCovariance(), 1e3);
  EXPECT_EQ(j["frame"], "base");
  EXPECT_NEAR(j["translation"][0].get<double>(), 2.0, 1e-12);
  EXPECT_NEAR(j["translation"][1].get<double>(), 1.0, 1e-12);
  EXPECT_NEAR(j["translation"][2].get<double>(), 3.0, 1e-12);
}

TEST(TranslationSigma, MatchesSampledRightPerturbations) {
  // rwhe-kuka2's X: 121.656° about (−0.5692, 0.6045, −0.5573), t = (14.4, −108.1, −81.7) mm.
  const Eigen::Vector3d axis = Eigen::Vector3d(-0.5692, 0.6045, -0.5573).normalized();
  Pose X = Pose::Identity();
  X.linear() = Eigen::AngleAxisd(121.656 * M_PI / 180.0, axis).toRotationMatrix();
  X.translation() << 0.0144, -0.1081, -0.0817;
  // A full covariance: σ 0.6–1.7° and 1–3 mm, every pair correlated.
  Matrix6d L;
  L << 1e-2, 0, 0, 0, 0, 0,              //
      4e-3, 2e-2, 0, 0, 0, 0,            //
      -3e-3, 5e-3, 3e-2, 0, 0, 0,        //
      6e-4, -4e-4, 2e-4, 1e-3, 0, 0,     //
      -5e-4, 8e-4, 3e-4, 6e-4, 2e-3, 0,  //
      2e-4, -6e-4, 9e-4, -8e-4, 1e-3, 3e-3;
  const Matrix6d C = L * L.transpose();
  const Eigen::Matrix3d predicted = TranslationCovarianceInParent(X, C);

  constexpr int kSamples = 40000;
  std::mt19937_64 rng(20261125);
  hecal::NormalDistribution normal;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d sum2 = Eigen::Matrix3d::Zero();
  for (int s = 0; s < kSamples; ++s) {
    Vector6d z;
    for (int k = 0; k < 6; ++k) z(k) = normal(rng);
    const Eigen::Vector3d t = (X * se3::Exp(L * z)).translation() - X.translation();
    sum += t;
    sum2 += t * t.transpose();
  }
  const Eigen::Vector3d mean = sum / kSamples;
  const Eigen::Matrix3d sampled = (sum2 - kSamples * mean * mean.transpose()) / (kSamples - 1);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      // Standard error of a sample covariance entry: sqrt((Σii Σjj + Σij²) / N).
      const double se = std::sqrt(
          (predicted(i, i) * predicted(j, j) + predicted(i, j) * predicted(i, j)) / kSamples);
      EXPECT_NEAR(sampled(i, j), predicted(i, j), 4.0 * se) << i << ", " << j;
    }
    // The child-frame (camera-axis) variance is not the parent-frame one on this rotation: the
    // test tells the two apart.
    const double se = std::sqrt(2.0 / kSamples) * predicted(i, i);
    EXPECT_GT(std::abs(sampled(i, i) - C(3 + i, 3 + i)), 10.0 * se) << i;
  }
}

}  // namespace
}  // namespace hecal::report
