#include "hecal/handeye/daniilidis.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <numbers>

#include "hecal/core/error.h"
#include "hecal/geometry/so3.h"
#include "testing/handeye_solver_suite.h"

namespace hecal::handeye {
namespace {

testing::ProblemSolver Daniilidis() {
  return testing::FromMotionSolver([](const auto& motions) { return SolveDaniilidis(motions); });
}

TEST(Daniilidis, TwoSmallestSingularValuesVanishWithoutNoise) {
  for (handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    const testing::Scene data = testing::ThesisCase(setup, 10, 7);
    DaniilidisReport report;
    SolveDaniilidis(AllPairMotions(data.MeasuredProblem()), &report);
    const auto& sigma = report.singular_values;
    // Square roots of eigenvalues of TᵀT: resolution ~1e-8 σ₁.
    EXPECT_LT(sigma(6), 1e-6 * sigma(0));
    EXPECT_LT(sigma(7), 1e-6 * sigma(0));
    EXPECT_GT(sigma(5), 1e-3 * sigma(0));
    EXPECT_TRUE(report.rejected.empty());
  }
}

TEST(Daniilidis, NoCatastrophicTrialWithNoise) {
  EXPECT_LT(testing::RunNoisyStudy(Daniilidis(), 200, 5000).worst_rotation_deg, 10.0);
}

// Gaussian noise is not an inconsistency: on thesis-protocol data with 0.3 and 1 mm / degree the
// check keeps all but a few percent of the motions.
TEST(Daniilidis, NoisyDataLoseFewMotionsToTheConsistencyCheck) {
  for (double sigma : {0.3, 1.0}) {
    size_t rejected = 0, total = 0;
    for (uint64_t seed = 0; seed < 40; ++seed) {
      const testing::Scene data = testing::ThesisCase(
          seed % 2 == 0 ? handeye::Setup::kEyeInHand : handeye::Setup::kEyeToHand, 15, 300 + seed,
          sigma * std::numbers::pi / 180.0, sigma * 1e-3);
      const std::vector<Motion> motions = AllPairMotions(data.MeasuredProblem());
      DaniilidisReport report;
      SolveDaniilidis(motions, &report);
      rejected += report.rejected.size();
      total += motions.size();
    }
    std::printf("sigma %.1f: %zu of %zu motions rejected\n", sigma, rejected, total);
    EXPECT_LT(rejected, total / 20);
  }
}

// One station's camera pose is off by 5° and 2 cm: exactly the motions that use it break the
// scalar-part equality and are rejected; the rest still give X exactly.
TEST(Daniilidis, ConsistencyCheckRejectsMotionsOfACorruptedStation) {
  constexpr int kBad = 3;
  for (handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    testing::Scene data = testing::ThesisCase(setup, 8, 21);
    data.T_camera_target[kBad] =
        data.T_camera_target[kBad] *
        MakePose(so3::Exp(Eigen::Vector3d(0.05, -0.06, 0.03)), Eigen::Vector3d(0.02, 0.0, 0.0));
    const std::vector<Motion> motions = AllPairMotions(data.MeasuredProblem());
    DaniilidisReport report;
    const Pose X = SolveDaniilidis(motions, &report);
    std::vector<int> expected;
    for (size_t k = 0; k < motions.size(); ++k) {
      if (motions[k].i == kBad || motions[k].j == kBad) expected.push_back(static_cast<int>(k));
    }
    EXPECT_EQ(report.rejected, expected);
    testing::ExpectPoseNear(X, data.X, 1e-9, "X");
  }
}

// Motions built directly: 4 with a wrong rotation angle (zero pitch, so only the real scalar
// part disagrees), 4 with a wrong pitch, 2 consistent. Each check alone rejects 4 of 10, together
// 8 of 10: the data are not hand–eye motions and the solver says so.
TEST(Daniilidis, ReportsWhenMostMotionsAreInconsistent) {
  std::mt19937_64 rng(5);
  const Pose X = testing::RandomPose(rng, 0.1);
  std::vector<Motion> motions;
  for (int k = 0; k < 10; ++k) {
    const Eigen::Vector3d axis = testing::RandomUnitVector(rng);
    Eigen::Vector3d t = testing::RandomPose(rng).translation();
    t -= t.dot(axis) * axis;  // zero pitch
    Pose B = MakePose(so3::Exp(1.2 * axis), t);
    Pose A = X * B * X.inverse();
    if (k < 4) B.linear() = so3::Exp(1.4 * axis);        // angle differs
    if (k >= 4 && k < 8) B.translation() += 0.1 * axis;  // pitch differs
    motions.push_back({A, B, 0, k + 1});
  }
  EXPECT_THROW(SolveDaniilidis(motions), DegenerateError);
}

TEST(Daniilidis, DegenerateDataThrow) {
  testing::ExpectDegenerateDataThrow(Daniilidis());
}

// The translation normalisation makes the result independent of the length unit.
TEST(Daniilidis, ResultDoesNotDependOnTheLengthUnit) {
  const testing::Scene data = testing::ThesisCase(handeye::Setup::kEyeInHand, 10, 31, 0.01, 1e-3);
  std::vector<Motion> motions = AllPairMotions(data.MeasuredProblem());
  const Pose X_m = SolveDaniilidis(motions);
  for (Motion& motion : motions) {
    motion.A.translation() *= 1000.0;
    motion.B.translation() *= 1000.0;
  }
  const Pose X_mm = SolveDaniilidis(motions);
  EXPECT_LT(so3::Distance(X_m.linear(), X_mm.linear()), 1e-10);
  EXPECT_LT((1000.0 * X_m.translation() - X_mm.translation()).norm(), 1e-7);
}

}  // namespace
}  // namespace hecal::handeye
