#include "hecal/plan/station_design.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "hecal/core/random_draws.h"
#include "hecal/estimation/bound.h"
#include "hecal/sim/thesis_protocol.h"

namespace hecal::plan {
namespace {

// A pool of thesis-protocol stations (sim/thesis_protocol.h) for one truth.
struct Pool {
  Scene scene;
  std::vector<ViewCandidate> candidates;
};

Pool ThesisPool(int size, uint64_t seed) {
  sim::ProtocolOptions protocol;
  std::mt19937_64 rng(seed);
  const sim::HandEyeTruth truth = sim::DrawTruth(protocol, rng);
  hecal::UniformRealDistribution tilt(-0.7, 0.7), spin(-3.1, 3.1), cube(-0.5, 0.5);
  Pool pool{{protocol.setup, truth.X, truth.Z}, {}};
  for (int k = 0; k < size; ++k) {
    // Drawn last to first: the order these tests' data were generated in.
    const double z = cube(rng), y = cube(rng), x = cube(rng);
    const double gamma = spin(rng), beta = tilt(rng), alpha = tilt(rng);
    const Pose T_target_camera =
        sim::CameraInTarget(protocol, alpha, beta, gamma, Eigen::Vector3d(x, y, z));
    pool.candidates.push_back(
        {sim::RobotPoseFor(protocol.setup, truth, T_target_camera), T_target_camera.inverse()});
  }
  return pool;
}

const estimation::PoseSigma kRobot{0.001, 0.0001};
const estimation::PoseSigma kCamera{0.002, 0.0005};

TEST(StationDesign, XCovarianceIsTheBoundsXBlock) {
  const Pool pool = ThesisPool(12, 1);
  const auto information = CandidateInformation(pool.candidates, {pool.scene}, kRobot, kCamera);
  Matrix12d sum = Matrix12d::Zero();
  handeye::Problem problem{pool.scene.setup, {}, {}};
  for (size_t c = 0; c < pool.candidates.size(); ++c) {
    sum += information[c][0];
    problem.A.push_back(pool.candidates[c].T_base_gripper);
    problem.B.push_back(pool.candidates[c].T_camera_target);
  }
  const estimation::AccuracyBound bound =
      estimation::FirstOrderBound(problem, pool.scene.X, pool.scene.Z, kRobot, kCamera);
  const Eigen::Matrix<double, 6, 6> expected = bound.covariance.topLeftCorner<6, 6>();
  EXPECT_LT((XCovariance(sum) - expected).norm(), 1e-6 * expected.norm());
}

TEST(StationDesign, ChosenStationsBeatEveryRandomSubset) {
  const Pool pool = ThesisPool(200, 2);
  const auto information = CandidateInformation(pool.candidates, {pool.scene}, kRobot, kCamera);
  const std::vector<Matrix12d> zero = {Matrix12d::Zero()};
  const auto value = [&](const std::vector<int>& stations) {
    Matrix12d sum = Matrix12d::Zero();
    for (int c : stations) sum += information[static_cast<size_t>(c)][0];
    return XLogDet(sum);
  };
  const std::vector<int> chosen = ChooseStations(information, zero, 8);
  const std::vector<int> greedy = ChooseStations(information, zero, 8, /*exchange=*/false);
  ASSERT_EQ(chosen.size(), 8u);
  EXPECT_GE(value(chosen), value(greedy) - 1e-9);  // the exchange never loses
  std::vector<int> sorted = chosen;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end());  // distinct
  std::mt19937_64 rng(3);
  std::vector<int> all(200);
  for (int k = 0; k < 200; ++k) all[static_cast<size_t>(k)] = k;
  for (int trial = 0; trial < 100; ++trial) {
    std::shuffle(all.begin(), all.end(), rng);
    EXPECT_GT(value(chosen), value({all.begin(), all.begin() + 8}));
  }
}

}  // namespace
}  // namespace hecal::plan
