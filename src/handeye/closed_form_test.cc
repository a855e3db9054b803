#include "hecal/handeye/closed_form.h"

#include <gtest/gtest.h>

#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "hecal/geometry/so3.h"
#include "testing/handeye_solver_suite.h"
#include "testing/moveit_dataset.h"

namespace hecal::handeye {
namespace {

TEST(ClosedForms, NamesAreTheCliNamesInEnumOrder) {
  const std::vector<std::string> expected = {
      "tsai-lenz",  "park-martin", "horaud",  "horaud-nonlinear",
      "chou-kamel", "daniilidis",  "andreff", "shiu-ahmad",
      "shah",       "li"};
  std::vector<std::string> names;
  for (const ClosedFormInfo& info : ClosedForms()) {
    EXPECT_EQ(info.form, static_cast<ClosedForm>(names.size())) << info.name;
    EXPECT_EQ(&Info(info.form), &info);
    EXPECT_GT(info.summary.size(), 40u) << info.name;
    EXPECT_EQ(info.summary.find('\n'), std::string_view::npos) << info.name;
    names.emplace_back(info.name);
  }
  EXPECT_EQ(names, expected);
  EXPECT_THROW(Info(static_cast<ClosedForm>(expected.size())), std::invalid_argument);
}

// Stations that differ by EXACT half-turns about the coordinate axes (relative rotations of
// exactly π, where the quaternion scalar parts vanish and canonical signs are arbitrary), plus
// two generic stations.
TEST(ClosedForms, EveryClosedFormIsExactWithExactHalfTurnsBetweenStations) {
  constexpr double pi = std::numbers::pi;
  std::mt19937_64 rng(77);
  const Eigen::Matrix3d R0 = testing::RandomRotation(rng);
  std::vector<Pose> T_target_camera;
  for (const Eigen::Vector3d& omega :
       {Eigen::Vector3d(0.0, 0.0, 0.0), Eigen::Vector3d(pi, 0.0, 0.0),
        Eigen::Vector3d(0.0, pi, 0.0), Eigen::Vector3d(0.0, 0.0, pi),
        Eigen::Vector3d(0.3, -0.5, 0.2), Eigen::Vector3d(-0.7, 0.1, 0.9)}) {
    T_target_camera.push_back(
        MakePose(R0 * so3::Exp(omega), testing::RandomPose(rng, 0.5).translation()));
  }
  for (handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    const testing::Scene data = testing::CaseFromCameraPoses(setup, T_target_camera, rng);
    for (const ClosedFormInfo& info : ClosedForms()) {
      SCOPED_TRACE(std::string(info.name) + " " + std::string(SetupName(setup)));
      const Solution solution = SolveClosedForm(info.form, data.MeasuredProblem());
      testing::ExpectPoseNear(solution.X, data.X, 1e-9, "X");
      testing::ExpectPoseNear(solution.Z, data.Z, 1e-9, "Z");
    }
  }
}

// Real eye-to-hand data with relative rotations up to 175°: every closed form meets the upstream
// expectation of moveit_calibration's solver test (SOURCE.md): translation and the Euler angles
// eulerAngles(0, 1, 2) each within Eigen's isApprox(·, 0.01).
TEST(ClosedForms, EveryClosedFormMeetsTheMoveItExpectation) {
  const Problem problem = testing::LoadMoveItProblem();
  ASSERT_EQ(problem.A.size(), 50u);
  for (const ClosedFormInfo& info : ClosedForms()) {
    const Pose X = SolveClosedForm(info.form, problem).X;
    const Eigen::Vector3d euler = X.linear().eulerAngles(0, 1, 2);
    std::printf("moveit %-16s t = (%.4f, %.4f, %.4f) m, euler = (%.4f, %.4f, %.4f) rad\n",
                std::string(info.name).c_str(), X.translation().x(), X.translation().y(),
                X.translation().z(), euler.x(), euler.y(), euler.z());
    EXPECT_TRUE(X.translation().isApprox(testing::kMoveItTranslation, 0.01)) << info.name;
    EXPECT_TRUE(euler.isApprox(testing::kMoveItEulerXyz, 0.01)) << info.name;
  }
}

}  // namespace
}  // namespace hecal::handeye
