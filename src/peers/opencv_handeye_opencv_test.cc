// The OpenCV peers' convention mapping (opencv_handeye.h), tested noise-free on benign data where
// every OpenCV 4.6 method works: relative rotations below ~60°, well spread axes.
#include <gtest/gtest.h>

#include <random>

#include "hecal/core/random_draws.h"
#include "hecal/geometry/so3.h"
#include "hecal/peers/opencv_handeye.h"
#include "testing/random_poses.h"

namespace hecal::peers {
namespace {

struct Data {
  Pose X, Z;
  std::vector<Pose> T_base_gripper, T_camera_target;
};

// Camera within ±0.5 rad of a nominal orientation looking at the target from 1 m.
Data BenignData(handeye::Setup setup, int stations, uint64_t seed) {
  std::mt19937_64 rng(seed);
  Data data;
  const Pose small = testing::RandomPose(rng, 0.05);
  const Pose large = testing::RandomPose(rng, 1.0);
  data.X = setup == handeye::Setup::kEyeInHand ? small : large;
  data.Z = setup == handeye::Setup::kEyeInHand ? large : small;
  hecal::UniformRealDistribution angle(0.1, 0.5);
  hecal::UniformRealDistribution box(-0.3, 0.3);
  for (int i = 0; i < stations; ++i) {
    // Drawn last to first: the order these tests' data were generated in.
    const double z = box(rng);
    const double y = box(rng);
    const double x = box(rng);
    const Pose T_target_camera = MakePose(so3::Exp(testing::RandomRotationVector(rng, angle(rng))),
                                          Eigen::Vector3d(x, y, -1.0 + z));
    const Pose A = data.Z * T_target_camera * data.X.inverse();
    data.T_base_gripper.push_back(setup == handeye::Setup::kEyeInHand ? A : A.inverse());
    data.T_camera_target.push_back(T_target_camera.inverse());
  }
  return data;
}

double RotationError(const Pose& a, const Pose& b) {
  return so3::Distance(a.linear(), b.linear());
}
double TranslationError(const Pose& a, const Pose& b) {
  return (a.translation() - b.translation()).norm();
}

class OpenCvPeer
    : public ::testing::TestWithParam<std::tuple<handeye::ClosedForm, handeye::Setup>> {};

TEST_P(OpenCvPeer, RecoversXAndZNoiseFreeInBothSetups) {
  const auto [method, setup] = GetParam();
  for (uint64_t seed : {1u, 2u, 3u}) {
    const Data data = BenignData(setup, 10, seed);
    const handeye::Problem problem =
        handeye::MakeProblem(setup, data.T_base_gripper, data.T_camera_target);
    const handeye::Solution solution = SolveWithOpenCv(method, problem);
    // OpenCV's solvers are accurate to ~1e-9 on exact data; 1e-6 leaves room for its SVDs.
    EXPECT_LT(RotationError(solution.X, data.X), 1e-6) << handeye::Info(method).name;
    EXPECT_LT(TranslationError(solution.X, data.X), 1e-6) << handeye::Info(method).name;
    EXPECT_LT(RotationError(solution.Z, data.Z), 1e-6) << handeye::Info(method).name;
    EXPECT_LT(TranslationError(solution.Z, data.Z), 1e-6) << handeye::Info(method).name;
  }
}

INSTANTIATE_TEST_SUITE_P(AllPeers, OpenCvPeer,
                         ::testing::Combine(::testing::ValuesIn(OpenCvPeerMethods()),
                                            ::testing::Values(handeye::Setup::kEyeInHand,
                                                              handeye::Setup::kEyeToHand)),
                         [](const auto& test_info) {
                           std::string name(handeye::Info(std::get<0>(test_info.param)).name);
                           name += std::get<1>(test_info.param) == handeye::Setup::kEyeInHand
                                       ? "_EyeInHand"
                                       : "_EyeToHand";
                           for (char& c : name) {
                             if (c == '-') c = '_';
                           }
                           return name;
                         });

TEST(OpenCvPeer, TheSevenOpenCvMethodsAreMapped) {
  const std::vector<handeye::ClosedForm> methods = OpenCvPeerMethods();
  EXPECT_EQ(methods.size(), 7u);
  EXPECT_TRUE(HasOpenCvPeer(handeye::ClosedForm::kDaniilidis));
  EXPECT_FALSE(HasOpenCvPeer(handeye::ClosedForm::kShiuAhmad));
  EXPECT_FALSE(HasOpenCvPeer(handeye::ClosedForm::kChouKamel));
}

TEST(OpenCvPeer, TheEyeToHandInversionMatters) {
  // Feeding eye-to-hand robot poses as if the camera were on the hand (no inverse) must give a
  // wrong X: the mapping above is not vacuous.
  const Data data = BenignData(handeye::Setup::kEyeToHand, 10, 4);
  const handeye::Problem wrong =
      handeye::MakeProblem(handeye::Setup::kEyeInHand, data.T_base_gripper, data.T_camera_target);
  const handeye::Solution solution = SolveWithOpenCv(handeye::ClosedForm::kParkMartin, wrong);
  EXPECT_GT(RotationError(solution.X, data.X) + TranslationError(solution.X, data.X), 1e-2);
}

TEST(OpenCvPeer, PreparedInputHoldsTheInverseRobotPoses) {
  const Data data = BenignData(handeye::Setup::kEyeInHand, 3, 5);
  const handeye::Problem problem =
      handeye::MakeProblem(handeye::Setup::kEyeInHand, data.T_base_gripper, data.T_camera_target);
  const OpenCvInput input = PrepareOpenCvInput(problem);
  ASSERT_EQ(input.R_A_inv.size(), 3u);
  const Pose A_inv = problem.A[1].inverse();
  EXPECT_NEAR(input.R_A_inv[1].at<double>(0, 2), A_inv.linear()(0, 2), 1e-15);
  EXPECT_NEAR(input.t_A_inv[1].at<double>(2, 0), A_inv.translation()(2), 1e-15);
  EXPECT_NEAR(input.t_B[2].at<double>(1, 0), problem.B[2].translation()(1), 1e-15);
}

}  // namespace
}  // namespace hecal::peers
