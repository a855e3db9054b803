#include "hecal/estimation/station_selection.h"

#include <gtest/gtest.h>

#include <random>

#include "hecal/core/random_draws.h"
#include "hecal/estimation/calibrate.h"
#include "hecal/estimation/initialization.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/geometry/se3.h"
#include "testing/handeye_cases.h"
#include "testing/options_validity.h"
#include "testing/scene.h"

namespace hecal::estimation {
namespace {

// A moderate outlier (a 4° robot error against 0.5° noise per axis) is rejected, and it alone.
TEST(SelectStations, AModerateOutlierIsRejected) {
  testing::Scene data =
      testing::ThesisCase(handeye::Setup::kEyeInHand, 15, 41, 0.5 * kRadiansPerDegree, 1e-3);
  Vector6d offset;
  offset << 0.0, 4.0 * kRadiansPerDegree, 0.0, 0.0, 0.0, 0.0;
  data.T_base_gripper[4] = data.T_base_gripper[4] * se3::Exp(offset);
  const StationSelection selection = SelectStations(data.MeasuredProblem(), {});
  EXPECT_EQ(selection.Rejected(), std::vector<int>{4});
  EXPECT_FALSE(selection.too_many);
  EXPECT_GT(selection.tests[4].statistic, selection.tests[4].threshold);
  EXPECT_GE(selection.rounds, 1);
}

// Clean data: over 40 data sets of 20 stations (800 stations, 1 mm / 1°, noise estimated) at
// most 1% of the stations are rejected — the test's level is 0.27%.
TEST(SelectStations, CleanDataLoseAlmostNothing) {
  int rejected = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const handeye::Setup setup =
        trial % 2 == 0 ? handeye::Setup::kEyeInHand : handeye::Setup::kEyeToHand;
    const testing::Scene data =
        testing::ThesisCase(setup, 20, 600 + trial, kRadiansPerDegree, 1e-3);
    rejected += static_cast<int>(SelectStations(data.MeasuredProblem(), {}).Rejected().size());
  }
  EXPECT_LE(rejected, 8);
}

// Two gross outliers, left out by the consensus: the first round's set is kept, and its fit is
// returned — ml from every closed-form start on the stations kept, exactly — and Calibrate's result
// is the same bit for bit as calibrating those stations alone without rejection.
TEST(SelectStations, TheFirstRoundFitIsMlOnTheStationsKept) {
  testing::Scene data =
      testing::ThesisCase(handeye::Setup::kEyeToHand, 20, 45, kRadiansPerDegree, 1e-3);
  std::mt19937_64 rng(5);
  const std::vector<int> replaced = testing::ReplaceRobotPoses(&data, 2, rng);
  const handeye::Problem problem = data.MeasuredProblem();
  StationSelectionOptions options;
  options.robot_sigma = options.camera_sigma = PoseSigma{kRadiansPerDegree, 1e-3};
  const StationSelection selection = SelectStations(problem, options);
  ASSERT_EQ(selection.rounds, 1);
  ASSERT_TRUE(selection.fit.has_value());
  for (int i : replaced) EXPECT_FALSE(selection.used[static_cast<size_t>(i)]) << i;
  const handeye::Problem kept = handeye::SubProblem(problem, selection.used);
  MlOptions ml;
  ml.robot_sigma = options.robot_sigma;
  ml.camera_sigma = options.camera_sigma;
  const MlResult direct = RefineMl(kept, StartingSolutions(kept), ml);
  EXPECT_TRUE(selection.fit->X.isApprox(direct.X, 0.0));
  EXPECT_TRUE(selection.fit->Z.isApprox(direct.Z, 0.0));

  CalibrateOptions calibrate;
  calibrate.robot_sigma = calibrate.camera_sigma = options.robot_sigma;
  calibrate.covariance.method = CovarianceMethod::kNone;
  calibrate.model_check = false;
  const CalibrationResult with_rejection = Calibrate(problem, calibrate);
  calibrate.reject_outliers = false;
  const CalibrationResult alone = Calibrate(kept, calibrate);
  EXPECT_TRUE(with_rejection.X.isApprox(alone.X, 0.0));
  EXPECT_TRUE(with_rejection.Z.isApprox(alone.Z, 0.0));
  EXPECT_EQ(with_rejection.rejected.size(), 2u);
}

// More stations fail the test than may be rejected — here the given sigmas are 20 times too
// small: nothing is rejected and too_many says why.
TEST(SelectStations, TooManyFlaggedRejectsNothing) {
  const testing::Scene data =
      testing::ThesisCase(handeye::Setup::kEyeToHand, 10, 42, kRadiansPerDegree, 1e-3);
  StationSelectionOptions options;
  options.robot_sigma = options.camera_sigma = PoseSigma{0.05 * kRadiansPerDegree, 5e-5};
  const StationSelection selection = SelectStations(data.MeasuredProblem(), options);
  EXPECT_TRUE(selection.too_many);
  EXPECT_TRUE(selection.Rejected().empty());
  EXPECT_GT(selection.flagged, 3);
}

// Four stations cannot spare one: nothing is tested, every station is used.
TEST(SelectStations, FourStationsAreAllUsed) {
  testing::Scene data =
      testing::ThesisCase(handeye::Setup::kEyeInHand, 4, 43, kRadiansPerDegree, 1e-3);
  std::mt19937_64 rng(1);
  testing::ReplaceRobotPoses(&data, 1, rng);
  const StationSelection selection = SelectStations(data.MeasuredProblem(), {});
  EXPECT_TRUE(selection.Rejected().empty());
  EXPECT_EQ(selection.rounds, 0);
  EXPECT_EQ(AllStations(4).used, std::vector<bool>(4, true));
}

// Per-station camera covariances (PnP poses): a station whose camera pose is ten times noisier
// than the others, and whose covariance says so, is kept; with one isotropic camera sigma it
// would be rejected.
TEST(SelectStations, PerStationCameraCovariancesKeepImpreciseViews) {
  std::mt19937_64 rng(44);
  testing::Scene data = testing::ThesisCase(handeye::Setup::kEyeInHand, 12, 44);
  std::vector<Matrix6d> covariances;
  hecal::NormalDistribution gaussian;
  for (size_t i = 0; i < data.T_camera_target.size(); ++i) {
    const double sigma_r = (i == 7 ? 1.0 : 0.1) * kRadiansPerDegree,
                 sigma_t = (i == 7 ? 5e-3 : 5e-4);
    Vector6d delta;
    for (int k = 0; k < 6; ++k) delta(k) = gaussian(rng) * (k < 3 ? sigma_r : sigma_t);
    if (i == 7) delta << 2.0 * sigma_r, -2.0 * sigma_r, 1.5 * sigma_r, 2.0 * sigma_t, 0, 0;
    data.T_camera_target[i] = data.T_camera_target[i] * se3::Exp(delta);
    Vector6d variances;
    variances << Eigen::Vector3d::Constant(sigma_r * sigma_r),
        Eigen::Vector3d::Constant(sigma_t * sigma_t);
    covariances.push_back(variances.asDiagonal());
  }
  StationSelectionOptions isotropic;
  isotropic.camera_sigma = PoseSigma{0.1 * kRadiansPerDegree, 5e-4};
  isotropic.robot_sigma = PoseSigma{0.01 * kRadiansPerDegree, 1e-5};
  EXPECT_EQ(SelectStations(data.MeasuredProblem(), isotropic).Rejected(), std::vector<int>{7});
  StationSelectionOptions per_station = isotropic;
  per_station.camera_covariances = covariances;
  EXPECT_TRUE(SelectStations(data.MeasuredProblem(), per_station).Rejected().empty());
}

TEST(StationSelectionOptions, IsValidNamesTheField) {
  using testing::RefusesNaming;
  const StationSelectionOptions defaults;
  EXPECT_TRUE(testing::IsValidOptions(defaults));
  EXPECT_TRUE(RefusesNaming(defaults, "StationSelectionOptions.robot_sigma", [](auto& o) {
    o.robot_sigma = PoseSigma{0.01, -0.001};
  }));
  EXPECT_TRUE(RefusesNaming(defaults, "StationSelectionOptions.camera_sigma", [](auto& o) {
    o.camera_sigma = PoseSigma{4.0, 0.001};
  }));
  EXPECT_TRUE(RefusesNaming(defaults, "StationSelectionOptions.camera_covariances", [](auto& o) {
    o.camera_covariances = {Matrix6d::Identity(), Matrix6d::Constant(std::nan(""))};
  }));
  EXPECT_TRUE(RefusesNaming(defaults, "ConsensusOptions.max_scored_stations",
                            [](auto& o) { o.consensus.max_scored_stations = 2; }));
}

}  // namespace
}  // namespace hecal::estimation
