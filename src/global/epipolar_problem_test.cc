// The cheiral ray error against its definition (a brute-force search over perturbed rays), its
// relation to the epipolar plane angle, and the camera motion of both setups.
#include "hecal/global/epipolar_problem.h"

#include <gtest/gtest.h>

#include <random>

#include "testing/epipolar_scenes.h"
#include "testing/random_poses.h"

namespace hecal::global {
namespace {

// E by definition: the smallest ε with t ∈ cone(C(a, ε) ∪ C(c, ε)); membership tested by
// searching rays a', c' on the caps' boundary circles (enough: the hull of two caps is the
// union of the cones spanned by pairs of boundary or interior rays) for t = λa' + μc'.
bool InHull(const Eigen::Vector3d& a, const Eigen::Vector3d& c, double eps,
            const Eigen::Vector3d& t) {
  // t ∈ hull iff no unit q with q·t > 0 and q·x ≤ 0 on both caps; sample q densely.
  std::mt19937_64 rng(3);
  for (int i = 0; i < 200000; ++i) {
    const Eigen::Vector3d q = testing::RandomUnitVector(rng);
    if (q.dot(t) > 1e-9 && q.dot(a) <= -std::sin(eps) && q.dot(c) <= -std::sin(eps)) {
      return false;
    }
  }
  return true;
}

TEST(CheiralRayError, MatchesTheSeparatingPlaneDefinition) {
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 6; ++trial) {
    const Eigen::Vector3d v = testing::RandomUnitVector(rng);
    const Eigen::Vector3d Ru = testing::RandomUnitVector(rng);
    const Eigen::Vector3d t = testing::RandomUnitVector(rng);
    const double E = CheiralRayError(v, Ru, t);
    ASSERT_GE(E, 0.0);
    if (E > 0.02) {
      EXPECT_FALSE(InHull(v, -Ru, E - 0.01, t)) << trial;
    }
    EXPECT_TRUE(InHull(v, -Ru, E + 0.01, t)) << trial;
  }
}

TEST(CheiralRayError, IsZeroInsideTheWedgeAndAtMostThePlaneAngleNearIt) {
  const Eigen::Vector3d v = Eigen::Vector3d(0.1, 0.0, 1.0).normalized();
  const Eigen::Vector3d Ru = Eigen::Vector3d(-0.3, 0.0, 1.0).normalized();
  // The baseline t = λv − μRu for λ, μ > 0 lies in the wedge: error 0.
  EXPECT_EQ(CheiralRayError(v, Ru, 2.0 * v - 1.5 * Ru), 0.0);
  // Lifted out of the plane by 1 mrad: E ≤ the plane angle = 1 mrad.
  const Eigen::Vector3d in_plane = (v - Ru).normalized();
  const Eigen::Vector3d normal = v.cross(Ru).normalized();
  const Eigen::Vector3d lifted = std::cos(1e-3) * in_plane + std::sin(1e-3) * normal;
  EXPECT_NEAR(PlaneAngle(v, Ru, lifted), 1e-3, 1e-12);
  EXPECT_GT(CheiralRayError(v, Ru, lifted), 0.0);
  EXPECT_LE(CheiralRayError(v, Ru, lifted), 1e-3 + 1e-12);
  // The baseline on the wrong side (the point behind a camera): a large error.
  EXPECT_GT(CheiralRayError(v, Ru, -(2.0 * v - 1.5 * Ru)), 0.1);
}

TEST(EpipolarProblem, NoiseFreeScenesHaveZeroErrorAtTheTruthInBothSetups) {
  for (const auto setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    testing::EpipolarSceneSpec spec;
    spec.setup = setup;
    const testing::EpipolarScene scene = testing::MakeEpipolarScene(spec, 5);
    // The hand motions rebuilt from the robot poses through HandPose agree with the scene's.
    for (std::size_t m = 0; m < scene.problem.motions.size(); ++m) {
      const Pose B = HandPose(setup, scene.T_base_gripper[2 * m]).inverse() *
                     HandPose(setup, scene.T_base_gripper[2 * m + 1]);
      EXPECT_TRUE(B.isApprox(scene.problem.motions[m].hand, 1e-12));
    }
    EXPECT_LT(MaxRayError(scene.problem, scene.X), 1e-12);
    EXPECT_LT(MaxPlaneAngle(scene.problem, scene.X), 1e-12);
    Pose wrong = scene.X;
    wrong.translation() += Eigen::Vector3d(0.01, 0, 0);
    EXPECT_GT(MaxRayError(scene.problem, wrong), 1e-4);
  }
}

}  // namespace
}  // namespace hecal::global
