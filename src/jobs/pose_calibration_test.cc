// CalibrateFromPoses (pose_calibration.h) on exact synthetic stations (Z = A_i X B_i built from a
// chosen X and Z): one method recovers them; every method is accounted for as a result or a
// failure; the caller's notes come first in every result's warnings; a non-finite result is
// refused.
#include "hecal/jobs/pose_calibration.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "hecal/core/error.h"
#include "hecal/estimation/methods.h"
#include "testing/random_poses.h"

namespace hecal::jobs {
namespace {

// Eye-in-hand stations with T_base_gripper_i · X · T_camera_target_i = Z exactly.
PoseCalibrationInput ExactInput(const Pose& X, const Pose& Z, int stations) {
  std::mt19937_64 rng(11);
  std::vector<Pose> robot, camera;
  for (int i = 0; i < stations; ++i) {
    const Pose A = testing::RandomPose(rng, 0.5);
    robot.push_back(A);
    camera.push_back((A * X).inverse() * Z);
  }
  PoseCalibrationInput input;
  input.problem = handeye::MakeProblem(handeye::Setup::kEyeInHand, robot, camera);
  for (int i = 0; i < stations; ++i) input.station_ids.push_back(std::to_string(i + 1));
  input.plausibility = {handeye::Setup::kEyeInHand, robot, camera, true, true};
  input.notes = {"a note from the caller"};
  return input;
}

TEST(CalibrateFromPosesTest, OneMethodRecoversXAndZ) {
  std::mt19937_64 rng(5);
  const Pose X = testing::RandomPose(rng, 0.1);
  const Pose Z = testing::RandomPose(rng, 1.0);
  estimation::CalibrateOptions options;
  options.method = estimation::Method::kTsaiLenz;
  const report::ResultDocument document = CalibrateFromPoses(ExactInput(X, Z, 8), options, false);
  ASSERT_EQ(document.results.size(), 1u);
  EXPECT_FALSE(document.all_methods);
  EXPECT_EQ(document.station_ids.size(), 8u);
  EXPECT_TRUE(document.rejected.empty());
  const estimation::CalibrationResult& result = document.results[0];
  EXPECT_TRUE(result.X.isApprox(X, 1e-6));
  EXPECT_TRUE(result.Z.isApprox(Z, 1e-6));
  ASSERT_FALSE(result.warnings.empty());
  EXPECT_EQ(result.warnings[0], "a note from the caller");
}

TEST(CalibrateFromPosesTest, EveryMethodIsAResultOrAFailure) {
  std::mt19937_64 rng(6);
  const Pose X = testing::RandomPose(rng, 0.1);
  const Pose Z = testing::RandomPose(rng, 1.0);
  const report::ResultDocument document = CalibrateFromPoses(ExactInput(X, Z, 8), {}, true);
  EXPECT_TRUE(document.all_methods);
  EXPECT_EQ(document.results.size() + document.failures.size(), estimation::AllMethods().size());
  for (const estimation::CalibrationResult& result : document.results) {
    EXPECT_TRUE(result.X.isApprox(X, 1e-4)) << estimation::Info(result.method).name;
    EXPECT_EQ(result.warnings.at(0), "a note from the caller");
  }
}

TEST(CheckFiniteResultTest, RefusesANonFiniteSolution) {
  estimation::CalibrationResult result;
  EXPECT_NO_THROW(CheckFiniteResult(result));
  result.translation_rms = std::numeric_limits<double>::infinity();
  EXPECT_THROW(CheckFiniteResult(result), DegenerateError);
}

}  // namespace
}  // namespace hecal::jobs
