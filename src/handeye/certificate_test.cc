// The certificate of global optimality (certificate.h) against known truth: exact data certify
// at the truth with a zero gap; noisy data certify at the polished optimum with the lower bound
// below every other point's cost; a constructed local minimum is refused while the global one,
// reached from another start, is certified.
#include "hecal/handeye/certificate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "hecal/geometry/se3.h"
#include "hecal/geometry/so3.h"
#include "testing/handeye_cases.h"
#include "testing/random_poses.h"

namespace hecal::handeye {
namespace {

class CertificateTest : public ::testing::TestWithParam<Setup> {};

TEST_P(CertificateTest, ExactDataCertifyTheTruth) {
  const testing::Scene scene = testing::ThesisCase(GetParam(), 8, 81);
  const Certificate certificate = CertifyGlobalOptimum(scene.TrueProblem(), {scene.X, scene.Z},
                                                       WeightsFromSigmas(0.01, 0.001, 1.0));
  EXPECT_TRUE(certificate.certified)
      << certificate.min_eigenvalue << " " << certificate.stationarity;
  EXPECT_LT(certificate.cost, 1e-8);  // rounding at weights 10⁴ / 10⁶
  EXPECT_NEAR(certificate.gap, 0.0, 1e-9);
  EXPECT_LT(certificate.distance_rotation, 1e-9);
  EXPECT_LT(certificate.distance_translation, 1e-9);
}

// 1° / 1 mm per component on robot and camera, 10 stations: certified from the truth, the lower
// bound equal to the cost, and no other point (the truth, random rotations) below the bound.
TEST_P(CertificateTest, NoisyDataCertifyAndTheBoundHolds) {
  std::mt19937_64 rng(82);
  const double sigma_r = 1.0 * std::numbers::pi / 180, sigma_t = 1e-3;
  for (int trial = 0; trial < 20; ++trial) {
    const testing::Scene scene =
        testing::ThesisCase(GetParam(), 10, 820 + static_cast<uint64_t>(trial), sigma_r, sigma_t);
    const Problem problem = scene.MeasuredProblem();
    const ChordalWeights weights =
        WeightsFromSigmas(std::sqrt(2.0) * sigma_r, std::sqrt(2.0) * sigma_t, LengthScale(problem));
    const Certificate certificate = CertifyGlobalOptimum(problem, {scene.X, scene.Z}, weights);
    ASSERT_TRUE(certificate.certified) << "trial " << trial << ": " << certificate.min_eigenvalue;
    EXPECT_NEAR(certificate.gap, 0.0, 1e-6 * certificate.cost);
    // Any other point polished from elsewhere costs at least the bound.
    const Solution elsewhere{MakePose(testing::RandomRotation(rng), Eigen::Vector3d::Zero()),
                             MakePose(testing::RandomRotation(rng), Eigen::Vector3d::Zero())};
    const Certificate other = CertifyGlobalOptimum(problem, elsewhere, weights);
    EXPECT_GE(other.cost, certificate.lower_bound * (1 - 1e-9));
  }
}

// Four stations with 3° / 5 mm noise have local minima (in half the data sets, from 30 random
// starts): a polished point that costs more than the best is refused, the best certified.
TEST_P(CertificateTest, ALocalMinimumIsRefusedAndTheGlobalOneCertified) {
  std::mt19937_64 rng(83);
  const double sigma_r = 0.05, sigma_t = 0.005;
  bool found = false;
  for (int trial = 0; trial < 20 && !found; ++trial) {
    const testing::Scene scene =
        testing::ThesisCase(GetParam(), 4, 830 + static_cast<uint64_t>(trial), sigma_r, sigma_t);
    const Problem problem = scene.MeasuredProblem();
    const ChordalWeights weights = WeightsFromSigmas(sigma_r, sigma_t, LengthScale(problem));
    std::vector<Certificate> minima;
    for (int start = 0; start < 30; ++start) {
      const Solution from{MakePose(testing::RandomRotation(rng), Eigen::Vector3d::Zero()),
                          MakePose(testing::RandomRotation(rng), Eigen::Vector3d::Zero())};
      minima.push_back(CertifyGlobalOptimum(problem, from, weights));
    }
    const auto best = std::min_element(
        minima.begin(), minima.end(),
        [](const Certificate& a, const Certificate& b) { return a.cost < b.cost; });
    for (const Certificate& local : minima) {
      if (local.cost > best->cost * 1.01 &&
          local.stationarity < kCertificateStationarityTolerance) {
        found = true;
        EXPECT_FALSE(local.certified) << "a local minimum of cost " << local.cost
                                      << " above the best " << best->cost << " was certified";
        EXPECT_TRUE(best->certified) << best->min_eigenvalue;
        EXPECT_LE(best->lower_bound, local.cost);
        break;
      }
    }
  }
  EXPECT_TRUE(found) << "no local minimum found to refuse";
}

INSTANTIATE_TEST_SUITE_P(Setups, CertificateTest,
                         ::testing::Values(Setup::kEyeInHand, Setup::kEyeToHand));

}  // namespace
}  // namespace hecal::handeye
