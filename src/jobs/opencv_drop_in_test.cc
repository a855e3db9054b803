// The OpenCV drop-in jobs (opencv_drop_in.h) on exact synthetic stations of the thesis protocol
// (testing/scene.h): every method recovers X (and for robot-world Z) to rounding from matrices
// and from Rodrigues vectors; every refusal names its argument; parallel rotation axes are a
// DegenerateError.
#include "hecal/jobs/opencv_drop_in.h"

#include <gtest/gtest.h>

#include <limits>

#include "hecal/core/error.h"
#include "hecal/geometry/so3.h"
#include "testing/handeye_cases.h"

namespace hecal::jobs {
namespace {

DropInPoses FromPoses(const std::vector<Pose>& poses, const std::string& name, bool vectors) {
  DropInPoses out;
  out.R_name = "R_" + name;
  out.t_name = "t_" + name;
  for (const Pose& T : poses) {
    DropInRotation rotation;
    rotation.is_vector = vectors;
    if (vectors) {
      rotation.vector = so3::Log(T.linear());
    } else {
      rotation.matrix = T.linear();
    }
    out.R.push_back(rotation);
    out.t.push_back(T.translation());
  }
  return out;
}

double Error(const DropInTransform& estimate, const Pose& truth) {
  return std::max(so3::Distance(estimate.R, truth.linear()),
                  (estimate.t - truth.translation()).norm());
}

std::string Source(const auto& call) {
  try {
    call();
  } catch (const InputError& error) {
    return error.source() + ": " + error.problem();
  }
  return "no error";
}

TEST(OpenCvDropIn, EveryMethodRecoversXFromMatricesAndRodriguesVectors) {
  const testing::Scene scene = testing::ThesisCase(handeye::Setup::kEyeInHand, 10, 5);
  for (int method : {0, 1, 2, 3, 4, kDropInMl}) {
    for (bool vectors : {false, true}) {
      DropInCalibrateOptions options;
      options.method = method;
      const DropInTransform X =
          CalibrateHandEyeDropIn(FromPoses(scene.T_base_gripper, "gripper2base", vectors),
                                 FromPoses(scene.T_camera_target, "target2cam", false), options);
      EXPECT_LT(Error(X, scene.X), 1e-9) << method << " " << vectors;
    }
  }
}

TEST(OpenCvDropIn, RobotWorldRecoversBothUnknowns) {
  const testing::Scene scene = testing::ThesisCase(handeye::Setup::kEyeInHand, 10, 6);
  std::vector<Pose> base2gripper;
  for (const Pose& T : scene.T_base_gripper) base2gripper.push_back(T.inverse());
  for (int method : {0, 1, kDropInMl}) {
    DropInCalibrateOptions options;
    options.method = method;
    const RobotWorldDropIn result = CalibrateRobotWorldHandEyeDropIn(
        FromPoses(scene.T_camera_target, "world2cam", false),
        FromPoses(base2gripper, "base2gripper", false), options);
    EXPECT_LT(Error(result.base2world, scene.Z.inverse()), 1e-9) << method;
    EXPECT_LT(Error(result.gripper2cam, scene.X.inverse()), 1e-9) << method;
  }
}

TEST(OpenCvDropIn, RefusesWhatOpenCvTakesSilently) {
  const testing::Scene scene = testing::ThesisCase(handeye::Setup::kEyeInHand, 5, 7);
  const DropInPoses robot = FromPoses(scene.T_base_gripper, "gripper2base", false);
  const DropInPoses camera = FromPoses(scene.T_camera_target, "target2cam", false);
  DropInCalibrateOptions unknown;
  unknown.method = 5;
  EXPECT_EQ(Source([&] { CalibrateHandEyeDropIn(robot, camera, unknown); }).substr(0, 22),
            "method: unknown method");
  EXPECT_EQ(Source([&] { CalibrateRobotWorldHandEyeDropIn(camera, robot, unknown); }).substr(0, 6),
            "method");

  DropInPoses few = robot;
  few.R.resize(2);
  few.t.resize(2);
  DropInPoses few_camera = camera;
  few_camera.R.resize(2);
  few_camera.t.resize(2);
  EXPECT_EQ(Source([&] { CalibrateHandEyeDropIn(few, few_camera, {}); }).substr(0, 22),
            "R_gripper2base: has 2 ");
  EXPECT_EQ(Source([&] { CalibrateHandEyeDropIn(few, camera, {}); }).substr(0, 22),
            "R_target2cam: has 5 po");

  DropInPoses short_t = robot;
  short_t.t.pop_back();
  EXPECT_EQ(Source([&] { CalibrateHandEyeDropIn(short_t, camera, {}); }).substr(0, 19),
            "t_gripper2base: has");

  DropInPoses nan = camera;
  nan.t[3].x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(Source([&] { CalibrateHandEyeDropIn(robot, nan, {}); }),
            "t_target2cam: entry 3 is not finite (NaN or infinity)");

  DropInPoses scaled = robot;
  scaled.R[1].matrix *= 1.01;
  EXPECT_EQ(Source([&] { CalibrateHandEyeDropIn(scaled, camera, {}); }).substr(0, 50),
            "R_gripper2base: entry 1 is not a rotation matrix (");
  DropInPoses reflected = robot;
  reflected.R[2].matrix = -reflected.R[2].matrix;
  EXPECT_NE(Source([&] { CalibrateHandEyeDropIn(reflected, camera, {}); }).find("det R = -1"),
            std::string::npos);
}

TEST(OpenCvDropIn, ParallelRotationAxesAreDegenerate) {
  // Every robot rotation about z: the translation of X along z cannot be observed.
  std::vector<Pose> robot, camera;
  Pose X = Pose::Identity();
  X.linear() = so3::Exp(Eigen::Vector3d(0.2, -0.1, 0.3));
  X.translation() = Eigen::Vector3d(0.05, 0.02, 0.1);
  Pose Z = Pose::Identity();
  Z.translation() = Eigen::Vector3d(1.0, 0.0, 0.0);
  for (int i = 0; i < 6; ++i) {
    Pose A = Pose::Identity();
    A.linear() = so3::Exp(Eigen::Vector3d(0.0, 0.0, 0.4 * i));
    A.translation() = Eigen::Vector3d(0.1 * i, 0.05 * i * i, 0.3);
    robot.push_back(A);
    camera.push_back((A * X).inverse() * Z);
  }
  for (int method : {1, kDropInMl}) {
    DropInCalibrateOptions options;
    options.method = method;
    EXPECT_THROW(CalibrateHandEyeDropIn(FromPoses(robot, "gripper2base", false),
                                        FromPoses(camera, "target2cam", false), options),
                 DegenerateError)
        << method;
  }
}

}  // namespace
}  // namespace hecal::jobs
