#include "hecal/handeye/methods.h"

#include <gtest/gtest.h>

#include <numbers>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "hecal/geometry/so3.h"
#include "testing/handeye_solver_suite.h"
#include "testing/moveit_dataset.h"

namespace hecal::handeye {
namespace {

std::vector<Method> ClosedFormMethods() {
  std::vector<Method> methods;
  for (const MethodInfo& info : AllMethods()) {
    if (info.closed_form) methods.push_back(info.method);
  }
  return methods;
}

TEST(Methods, NamesAreTheDesignNamesAndRoundTrip) {
  const std::set<std::string> expected = {
      "tsai-lenz",  "park-martin", "horaud",  "horaud-nonlinear",
      "chou-kamel", "daniilidis",  "andreff", "shiu-ahmad",
      "shah",       "li",          "strobl",  "ml"};
  std::set<std::string> names;
  for (const MethodInfo& info : AllMethods()) {
    names.insert(std::string(info.name));
    EXPECT_EQ(ParseMethod(info.name), info.method);
    EXPECT_EQ(Info(info.method).name, info.name);
    EXPECT_GT(info.summary.size(), 40u) << info.name;
    EXPECT_EQ(info.summary.find('\n'), std::string_view::npos) << info.name;
    EXPECT_EQ(info.closed_form, info.method != Method::kStrobl && info.method != Method::kMl)
        << info.name;
  }
  EXPECT_EQ(names, expected);
  EXPECT_EQ(AllMethods().size(), expected.size());
  EXPECT_FALSE(ParseMethod("tsai").has_value());
  EXPECT_FALSE(ParseMethod("").has_value());
  EXPECT_FALSE(ParseMethod("Park-Martin").has_value());
  EXPECT_FALSE(ParseMethod("all").has_value());
}

TEST(Methods, RefinementsAreNotClosedForm) {
  const Problem problem = testing::ThesisCase(handeye::Setup::kEyeInHand, 5, 1).MeasuredProblem();
  EXPECT_THROW(SolveClosedForm(Method::kStrobl, problem), std::invalid_argument);
  EXPECT_THROW(SolveClosedForm(Method::kMl, problem), std::invalid_argument);
}

// Stations that differ by EXACT half-turns about the coordinate axes (relative rotations of
// exactly π, where the quaternion scalar parts vanish and canonical signs are arbitrary), plus
// two generic stations.
TEST(Methods, EveryClosedFormIsExactWithExactHalfTurnsBetweenStations) {
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
    for (Method method : ClosedFormMethods()) {
      SCOPED_TRACE(std::string(Info(method).name) + " " + std::string(SetupName(setup)));
      const Solution solution = SolveClosedForm(method, data.MeasuredProblem());
      testing::ExpectPoseNear(solution.X, data.X, 1e-9, "X");
      testing::ExpectPoseNear(solution.Z, data.Z, 1e-9, "Z");
    }
  }
}

// Real eye-to-hand data with relative rotations up to 175°: every closed form meets the upstream
// expectation of moveit_calibration's solver test (SOURCE.md): translation and the Euler angles
// eulerAngles(0, 1, 2) each within Eigen's isApprox(·, 0.01).
TEST(Methods, EveryClosedFormMeetsTheMoveItExpectation) {
  const Problem problem = testing::LoadMoveItProblem();
  ASSERT_EQ(problem.A.size(), 50u);
  for (Method method : ClosedFormMethods()) {
    const Pose X = SolveClosedForm(method, problem).X;
    const Eigen::Vector3d euler = X.linear().eulerAngles(0, 1, 2);
    std::printf("moveit %-16s t = (%.4f, %.4f, %.4f) m, euler = (%.4f, %.4f, %.4f) rad\n",
                std::string(Info(method).name).c_str(), X.translation().x(), X.translation().y(),
                X.translation().z(), euler.x(), euler.y(), euler.z());
    EXPECT_TRUE(X.translation().isApprox(testing::kMoveItTranslation, 0.01)) << Info(method).name;
    EXPECT_TRUE(euler.isApprox(testing::kMoveItEulerXyz, 0.01)) << Info(method).name;
  }
}

}  // namespace
}  // namespace hecal::handeye
