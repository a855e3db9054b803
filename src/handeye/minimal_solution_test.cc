#include "hecal/handeye/minimal_solution.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "hecal/geometry/angle_units.h"
#include "hecal/geometry/so3.h"
#include "hecal/handeye/shah.h"
#include "testing/handeye_cases.h"

namespace hecal::handeye {
namespace {

double Median(std::vector<double> values) {
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2),
                   values.end());
  return values[values.size() / 2];
}

// Noise-free data: any three stations of the thesis protocol give the true X and Z.
TEST(MinimalSolution, NoiseFreeTriplesAreExact) {
  for (handeye::Setup setup : {Setup::kEyeInHand, Setup::kEyeToHand}) {
    const testing::Scene data = testing::ThesisCase(setup, 8, 41);
    const Problem problem = data.MeasuredProblem();
    for (size_t a = 0; a + 2 < problem.A.size(); ++a) {
      const std::optional<Solution> solution = SolveMinimal(problem, a, a + 1, a + 2);
      ASSERT_TRUE(solution.has_value());
      EXPECT_LT(testing::Error(solution->X, data.X).rotation, 1e-10);
      EXPECT_LT(testing::Error(solution->X, data.X).translation, 1e-10);
      EXPECT_LT(testing::Error(solution->Z, data.Z).rotation, 1e-10);
      EXPECT_LT(testing::Error(solution->Z, data.Z).translation, 1e-10);
    }
  }
}

// Two motions about one axis do not fix X: no solution (Shah reports these degenerate too).
TEST(MinimalSolution, ParallelAxesGiveNoSolution) {
  testing::Scene data = testing::ThesisCase(Setup::kEyeInHand, 3, 7);
  Problem problem = data.MeasuredProblem();
  const Eigen::Vector3d axis = Eigen::Vector3d(0.3, -0.5, 0.8).normalized();
  const Pose X = data.X, Z = data.Z;
  for (int i = 0; i < 3; ++i) {
    problem.A[i] = problem.A[0];
    problem.A[i].linear() = problem.A[0].linear() * so3::Exp(0.4 * i * axis);
    problem.B[i] = X.inverse() * problem.A[i].inverse() * Z;  // exact: Z = A_i X B_i
  }
  EXPECT_FALSE(SolveMinimal(problem, 0, 1, 2).has_value());
  // The same stations with one motion about another axis are solved exactly.
  problem.A[2].linear() = problem.A[0].linear() * so3::Exp(Eigen::Vector3d(0.0, 0.5, 0.1));
  problem.B[2] = X.inverse() * problem.A[2].inverse() * Z;
  const std::optional<Solution> solution = SolveMinimal(problem, 0, 1, 2);
  ASSERT_TRUE(solution.has_value());
  EXPECT_LT(testing::Error(solution->X, X).rotation, 1e-10);
  EXPECT_LT(testing::Error(solution->X, X).translation, 1e-10);
}

// 1 mm / 1° on robot and camera, 300 random triples: the typical hypothesis is as accurate as
// Shah's least-squares solution of the same three stations (median error of X within 1.25× of
// Shah's in rotation and translation). The median, not the RMS: a few ill-conditioned triples
// are tens of degrees off with either solver, and the consensus ranks them last.
TEST(MinimalSolution, NoisyTriplesAsAccurateAsShah) {
  std::vector<double> minimal_rotation, minimal_translation, shah_rotation, shah_translation;
  for (handeye::Setup setup : {Setup::kEyeInHand, Setup::kEyeToHand}) {
    for (int trial = 0; trial < 150; ++trial) {
      const testing::Scene data =
          testing::ThesisCase(setup, 3, 900 + trial, kRadiansPerDegree, 1e-3);
      const Problem problem = data.MeasuredProblem();
      const std::optional<Solution> minimal = SolveMinimal(problem, 0, 1, 2);
      ASSERT_TRUE(minimal.has_value());
      const Solution shah = SolveShah(problem);
      minimal_rotation.push_back(testing::Error(minimal->X, data.X).rotation);
      minimal_translation.push_back(testing::Error(minimal->X, data.X).translation);
      shah_rotation.push_back(testing::Error(shah.X, data.X).rotation);
      shah_translation.push_back(testing::Error(shah.X, data.X).translation);
    }
  }
  const double rotation = Median(minimal_rotation), rotation_shah = Median(shah_rotation);
  const double translation = Median(minimal_translation),
               translation_shah = Median(shah_translation);
  std::printf("median error of X: minimal %.4f deg / %.2f mm, Shah %.4f deg / %.2f mm\n",
              rotation * kDegreesPerRadian, translation * 1e3, rotation_shah * kDegreesPerRadian,
              translation_shah * 1e3);
  EXPECT_LT(rotation, 1.25 * rotation_shah);
  EXPECT_LT(translation, 1.25 * translation_shah);
}

}  // namespace
}  // namespace hecal::handeye
