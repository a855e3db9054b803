// The perspective-corrected pose: exact on noise-free perspective views, where weak
// perspective's own inverse is biased.
#include "hecal/contour/perspective_pose.h"

#include <gtest/gtest.h>

#include <numbers>
#include <random>

#include "hecal/contour/contour_study.h"
#include "hecal/contour/perspective_view.h"
#include "hecal/core/error.h"
#include "hecal/core/random_draws.h"
#include "hecal/geometry/angle_units.h"

namespace hecal::contour {
namespace {

TEST(PerspectivePose, RecoversTheMotionOfAPerspectiveViewExactly) {
  // The paper's camera and target (at 5 m the perspective bias of the weak pose is tens of σ).
  const ContourCamera camera{6024.0, 5000.0};
  const Eigen::Matrix2Xd template_points = TemplateImage(DefaultTarget(), camera);
  const PerspectivePoseModel model(template_points, camera);
  std::mt19937_64 rng(5);
  hecal::UniformRealDistribution tilt(0.0, 40.0), spin(0.0, 360.0), lateral(-150, 150),
      depth(-2500, 1500);
  for (int trial = 0; trial < 40; ++trial) {
    // Drawn last to first: the order these tests' data were generated in.
    const double rz = spin(rng) * kRadiansPerDegree;
    const double ry = tilt(rng) * kRadiansPerDegree;
    const double rx = (5 + tilt(rng)) * kRadiansPerDegree;
    const Eigen::Matrix3d R = RotationZyx(rx, ry, rz);
    const double tz = depth(rng);
    const double ty = lateral(rng);
    const double tx = lateral(rng);
    const Eigen::Vector3d T(tx, ty, tz);
    const Vector6d S = model.PerspectiveShape(R, T);
    for (RotationForm form : {RotationForm::kZyx, RotationForm::kZxz}) {
      const ContourPose truth = CanonicalPose(R, T, form);
      const ContourPose weak = PoseFromShape(S, camera, form);
      const ContourPose corrected = model.Pose(S, form);
      // Its perspective image has the measured affine fit, and it is the form's member.
      EXPECT_LT((model.PerspectiveShape(corrected.rotation, corrected.translation) - S).norm(),
                1e-8);
      // The form's member, up to the rule's boundary (perspective moves the root slightly).
      if (form == RotationForm::kZyx) {
        EXPECT_GE(corrected.euler(1) + corrected.euler(2), -0.05) << trial;
      } else {
        EXPECT_GE(corrected.euler(0), -0.05) << trial;
        EXPECT_LE(corrected.euler(0), std::numbers::pi + 0.05) << trial;
      }
      if ((truth.rotation - R).norm() > 1e-9) continue;  // the truth is the other member
      EXPECT_LT((corrected.translation - T).norm(), 1e-6) << trial;
      EXPECT_LT((corrected.rotation - R).norm(), 1e-9) << trial;
      // Weak perspective alone is off by far more on these views.
      EXPECT_GT((weak.translation - T).norm() + 1e3 * (weak.rotation - truth.rotation).norm(), 1e-3)
          << trial;
    }
  }
}

TEST(PerspectivePose, IsTheWeakPoseWhenTheViewIsAffine) {
  // Pure in-plane motion at constant depth: the perspective image is exactly affine.
  const ContourCamera camera{6024.0, 5000.0};
  const PerspectivePoseModel model(TemplateImage(DefaultTarget(), camera), camera);
  const Eigen::Matrix3d R = RotationZyx(0, 0, 0.7);
  const Eigen::Vector3d T(30, -20, -1000);
  const Vector6d S = model.PerspectiveShape(R, T);
  EXPECT_LT((S - ShapeFromPose(R, T, camera)).norm(), 1e-9);
  EXPECT_LT((model.Pose(S, RotationForm::kZyx).translation - T).norm(), 1e-8);
}

TEST(PerspectivePose, SingularShapesAreRejected) {
  const ContourCamera camera{6024.0, 5000.0};
  const PerspectivePoseModel model(TemplateImage(DefaultTarget(), camera), camera);
  Vector6d edge_on = Vector6d::Zero();
  edge_on(3) = -1.0;
  EXPECT_THROW(model.Pose(edge_on, RotationForm::kZyx), DegenerateError);
}

}  // namespace
}  // namespace hecal::contour
