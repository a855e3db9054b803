#include "hecal/estimation/student_t.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "hecal/core/random_draws.h"
#include "hecal/estimation/initialization.h"
#include "hecal/estimation/ml.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/geometry/se3.h"
#include "testing/handeye_cases.h"

namespace hecal::estimation {
namespace {
constexpr int kDimension = 6;

// Squared norms of 6-vectors: standard normal (Gaussian) or a standard normal over the square
// root of an independent χ²(ν)/ν (multivariate t with ν degrees of freedom, scale 1).
std::vector<double> Distances(int n, double dof, uint64_t seed) {
  std::mt19937_64 rng(seed);
  hecal::NormalDistribution normal;
  std::chi_squared_distribution<double> chi2(dof > 0.0 ? dof : 1.0);
  std::vector<double> q(static_cast<size_t>(n));
  for (double& q_i : q) {
    double sum = 0.0;
    for (int k = 0; k < kDimension; ++k) sum += std::pow(normal(rng), 2);
    q_i = dof > 0.0 ? sum / (chi2(rng) / dof) : sum;
  }
  return q;
}

// Known values: the EM weight and the information factor of Lange, Little & Taylor (1989).
TEST(StudentTTest, WeightAndInformationFactor) {
  EXPECT_DOUBLE_EQ(StudentTWeight(6.0, 3.0, 6), 1.0);  // q = d: weight 1
  EXPECT_DOUBLE_EQ(StudentTWeight(0.0, 3.0, 6), 3.0);
  EXPECT_DOUBLE_EQ(StudentTInformationFactor(3.0, 6), 11.0 / 9.0);
  EXPECT_DOUBLE_EQ(StudentTInformationFactor(1e12, 6), 1.0 + 2.0 / (1e12 + 6.0));
}

// Identical distances have no tail at all: the Gaussian fits at least as well (ratio 0), and the
// profile scale is the Gaussian one, c = q / d.
TEST(StudentTTest, NoDispersionIsNotHeavyTailed) {
  const StudentTChoice choice = ChooseStudentT(std::vector<double>(20, 12.0), kDimension);
  EXPECT_FALSE(choice.chosen);
  EXPECT_DOUBLE_EQ(choice.likelihood_ratio, 0.0);
  EXPECT_THROW(ChooseStudentT({}, kDimension), std::invalid_argument);
  EXPECT_THROW(ChooseStudentT({1.0, -1.0}, kDimension), std::invalid_argument);
}

// 40 stations of multivariate t(3) distances: the t model is chosen far beyond the 5% threshold,
// ν near 3 and the scale near its true 1; 40 Gaussian ones: not chosen, with a margin. (Over
// seeds 1–1000 the Gaussian sets of 8, 15 and 40 stations chose the t model in 1.9%, 2.0% and
// 1.7% of the cases — below 5%: the grid ends at ν = 30 — and the t(3) sets in 66%, 90% and
// 100%.)
TEST(StudentTTest, ChoosesTheTModelOnHeavyTailsOnly) {
  const StudentTChoice heavy = ChooseStudentT(Distances(40, 3.0, 11), kDimension);
  EXPECT_TRUE(heavy.chosen);
  EXPECT_GT(heavy.likelihood_ratio, 4.0 * kStudentTThreshold);
  EXPECT_GE(heavy.dof, 2.0);
  EXPECT_LE(heavy.dof, 6.0);
  EXPECT_NEAR(heavy.scale, 1.0, 0.4);
  const StudentTChoice gaussian = ChooseStudentT(Distances(40, 0.0, 11), kDimension);
  EXPECT_FALSE(gaussian.chosen);
  EXPECT_LT(gaussian.likelihood_ratio, 0.5 * kStudentTThreshold);
}

// Through ml: 20 eye-in-hand stations with Gaussian noise (0.2°, 0.5 mm on robot and camera)
// and one camera pose off by 10σ on every component. The t model is chosen and weighs that
// station down: its covariance multiplier κ_ν / w_i is more than 5 times the median one (25.6
// against about 1), and the Gaussian station test still flags it (student_t.h, "What is an
// outlier"). Without the bad station the same data choose the Gaussian; with the robot sigma
// given the t model is not tried.
TEST(StudentTTest, DownWeightsAStationWithATenSigmaError) {
  const double rotation = 0.2 * kRadiansPerDegree, translation = 0.5e-3;
  testing::Scene data =
      testing::ThesisCase(handeye::Setup::kEyeInHand, 20, 21, rotation, translation);
  const auto solve = [](const testing::Scene& scene) {
    const handeye::Problem problem = scene.MeasuredProblem();
    return RefineMl(problem, Solutions(InitialSolutions(problem)), {});
  };
  const MlResult clean = solve(data);
  EXPECT_EQ(clean.noise.student_t_dof, 0.0);
  EXPECT_TRUE(clean.noise.station_scale.empty());

  constexpr size_t kBad = 7;
  Vector6d error;
  error << 10 * rotation, -10 * rotation, 10 * rotation, 10 * translation, 10 * translation,
      -10 * translation;
  data.T_camera_target[kBad] = data.T_camera_target[kBad] * se3::Exp(error);
  const MlResult heavy = solve(data);
  ASSERT_GT(heavy.noise.student_t_dof, 0.0);
  ASSERT_EQ(heavy.noise.station_scale.size(), 20u);
  std::vector<double> scale = heavy.noise.station_scale;
  std::nth_element(scale.begin(), scale.begin() + 10, scale.end());
  EXPECT_GT(heavy.noise.station_scale[kBad], 5.0 * scale[10]);
  EXPECT_TRUE(heavy.noise.stations[kBad].outlier);

  MlOptions given;
  given.robot_sigma = PoseSigma{rotation, translation};
  const handeye::Problem problem = data.MeasuredProblem();
  const MlResult robot_given = RefineMl(problem, Solutions(InitialSolutions(problem)), given);
  EXPECT_EQ(robot_given.noise.student_t_dof, 0.0);
  EXPECT_EQ(robot_given.noise.student_t_ratio, 0.0);
}

}  // namespace
}  // namespace hecal::estimation
