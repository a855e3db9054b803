#include "hecal/estimation/bound.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <stdexcept>
#include <vector>

#include "hecal/core/error.h"
#include "hecal/estimation/station_covariance.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/geometry/se3.h"
#include "testing/handeye_cases.h"

namespace hecal::estimation {
namespace {

// Independent check: the Cramér–Rao bound of the FULL measurement model, with the true camera
// poses T_i = T_camera_target_i as nuisance parameters, built by numeric differentiation and
// reduced to (X, Z) by inverting the whole information matrix. Measurements (docs/conventions.md):
//   camera  B̃_i = T_i · Exp(n_c)                     e_c = Log(T_i⁻¹ B̃_i)
//   robot   G̃_i = G_i(X, Z, T_i) · Exp(n_g)          e_g = Log(G_i⁻¹ G̃_i)
//   eye-in-hand  G_i = Z T_i⁻¹ X⁻¹,   eye-to-hand  G_i = X T_i Z⁻¹.
Eigen::MatrixXd FullModelBound(const testing::Scene& data, const PoseSigma& robot,
                               const PoseSigma& camera) {
  const int n = static_cast<int>(data.T_camera_target_true.size());
  const int parameters = 12 + 6 * n;
  const int measurements = 12 * n;
  auto predict_robot = [&](const Pose& X, const Pose& Z, const Pose& T) -> Pose {
    return data.setup == handeye::Setup::kEyeInHand ? Z * T.inverse() * X.inverse()
                                                    : X * T * Z.inverse();
  };
  // Stacked measurement residuals at the truth perturbed by δ (right perturbations).
  auto residuals = [&](const Eigen::VectorXd& delta) {
    const Pose X = data.X * se3::Exp(delta.segment<6>(0));
    const Pose Z = data.Z * se3::Exp(delta.segment<6>(6));
    Eigen::VectorXd e(measurements);
    for (int i = 0; i < n; ++i) {
      const Pose T = data.T_camera_target_true[i] * se3::Exp(delta.segment<6>(12 + 6 * i));
      e.segment<6>(12 * i) = se3::Log(T.inverse() * data.T_camera_target_true[i]);
      e.segment<6>(12 * i + 6) =
          se3::Log(predict_robot(X, Z, T).inverse() * data.T_base_gripper_true[i]);
    }
    return e;
  };
  Eigen::MatrixXd J(measurements, parameters);
  constexpr double h = 1e-6;
  for (int k = 0; k < parameters; ++k) {
    Eigen::VectorXd delta = Eigen::VectorXd::Zero(parameters);
    delta(k) = h;
    const Eigen::VectorXd plus = residuals(delta);
    delta(k) = -h;
    J.col(k) = (plus - residuals(delta)) / (2.0 * h);
  }
  Eigen::VectorXd weights(measurements);
  const Vector6d camera_variance = PoseCovariance(camera).diagonal();
  const Vector6d robot_variance = PoseCovariance(robot).diagonal();
  for (int i = 0; i < n; ++i) {
    weights.segment<6>(12 * i) = camera_variance.cwiseInverse();
    weights.segment<6>(12 * i + 6) = robot_variance.cwiseInverse();
  }
  const Eigen::MatrixXd information = J.transpose() * weights.asDiagonal() * J;
  return information.inverse().topLeftCorner(12, 12);
}

class BoundTest : public ::testing::TestWithParam<handeye::Setup> {};

TEST_P(BoundTest, EqualsTheFullModelBoundWithNuisanceStationPoses) {
  const testing::Scene data = testing::ThesisCase(GetParam(), 5, 31);
  const PoseSigma robot{1.0 * kRadiansPerDegree, 1e-3};
  const PoseSigma camera{0.5 * kRadiansPerDegree, 2e-3};
  const AccuracyBound bound =
      FirstOrderBound(data.MeasuredProblem(), data.X, data.Z, robot, camera);
  const Eigen::MatrixXd full = FullModelBound(data, robot, camera);
  EXPECT_LT((bound.covariance - full).norm(), 1e-5 * full.norm()) << bound.covariance << "\n\n"
                                                                  << full;
  EXPECT_NEAR(bound.rotation_rmse_X, std::sqrt(full.block(0, 0, 3, 3).trace()),
              1e-6 * kRadiansPerDegree);
  EXPECT_NEAR(bound.translation_rmse_X, std::sqrt(full.block(3, 3, 3, 3).trace()), 1e-9);
}

INSTANTIATE_TEST_SUITE_P(BothSetups, BoundTest,
                         ::testing::Values(handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand));

TEST(FirstOrderBound, ScalesWithTheNoiseAndShrinksWithMoreStations) {
  const testing::Scene data = testing::ThesisCase(handeye::Setup::kEyeInHand, 20, 32);
  const PoseSigma sigma{1.0 * kRadiansPerDegree, 1e-3};
  const PoseSigma twice{2.0 * kRadiansPerDegree, 2e-3};
  const handeye::Problem problem = data.MeasuredProblem();
  const AccuracyBound one = FirstOrderBound(problem, data.X, data.Z, sigma, sigma);
  const AccuracyBound two = FirstOrderBound(problem, data.X, data.Z, twice, twice);
  EXPECT_NEAR(two.rotation_rmse_X / one.rotation_rmse_X, 2.0, 1e-9);
  EXPECT_NEAR(two.translation_rmse_Z / one.translation_rmse_Z, 2.0, 1e-9);
  handeye::Problem fewer = problem;
  fewer.A.resize(5);
  fewer.B.resize(5);
  const AccuracyBound five = FirstOrderBound(fewer, data.X, data.Z, sigma, sigma);
  EXPECT_GT(five.rotation_rmse_X, one.rotation_rmse_X);
  EXPECT_GT(five.translation_rmse_X, one.translation_rmse_X);
}

// Per-station covariances: the information adds up over stations, so a station measured twice
// with covariance Σ carries the information of one station with covariance Σ / 2. Halving the
// covariances of stations 0–4 of ten equals appending copies of those five stations at the
// original sigmas — a known answer the sigma form cannot give.
TEST(FirstOrderBound, PerStationCovariancesWeightTheirStations) {
  const testing::Scene data = testing::ThesisCase(handeye::Setup::kEyeToHand, 10, 34);
  const handeye::Problem problem = data.MeasuredProblem();
  const PoseSigma robot{1.0 * kRadiansPerDegree, 1e-3};
  const PoseSigma camera{0.5 * kRadiansPerDegree, 2e-3};
  std::vector<Matrix6d> robot_covariance(10, PoseCovariance(robot));
  std::vector<Matrix6d> camera_covariance(10, PoseCovariance(camera));
  handeye::Problem repeated = problem;
  for (size_t i = 0; i < 5; ++i) {
    robot_covariance[i] /= 2.0;
    camera_covariance[i] /= 2.0;
    repeated.A.push_back(problem.A[i]);
    repeated.B.push_back(problem.B[i]);
  }
  const AccuracyBound weighted =
      FirstOrderBound(problem, data.X, data.Z, robot_covariance, camera_covariance);
  const AccuracyBound copies = FirstOrderBound(repeated, data.X, data.Z, robot, camera);
  EXPECT_TRUE(weighted.covariance.isApprox(copies.covariance, 1e-9));
  const AccuracyBound uniform = FirstOrderBound(problem, data.X, data.Z, robot, camera);
  EXPECT_LT(weighted.rotation_rmse_X, 0.95 * uniform.rotation_rmse_X);
  robot_covariance.pop_back();
  EXPECT_THROW(FirstOrderBound(problem, data.X, data.Z, robot_covariance, camera_covariance),
               std::invalid_argument);
}

TEST(FirstOrderBound, RejectsAZeroNoiseModel) {
  const testing::Scene data = testing::ThesisCase(handeye::Setup::kEyeInHand, 5, 33);
  EXPECT_THROW(FirstOrderBound(data.MeasuredProblem(), data.X, data.Z, PoseSigma{}, PoseSigma{}),
               DegenerateError);
}

}  // namespace
}  // namespace hecal::estimation
