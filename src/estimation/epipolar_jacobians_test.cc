// The target-free residuals and their Jacobians (epipolar_jacobians.h) against central finite
// differences of the Sampson residual itself (epipolar_residual.h) on a synthetic scene: J in the
// right perturbation δ of X, G in each station's hand-pose perturbation η (both stations of a
// motion, their columns in EpipolarStationIndex order), and r at δ = η = 0.
#include "epipolar_jacobians.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "epipolar_residual.h"
#include "hecal/core/error.h"
#include "testing/epipolar_scenes.h"

namespace hecal::estimation::detail {
namespace {

testing::EpipolarScene NoisyScene() {
  testing::EpipolarSceneSpec spec;
  spec.motions = 3;
  spec.pairs = 6;
  spec.pixel_sigma = 0.5;  // r ≠ 0, so that the test sees the residual's value too
  return testing::MakeEpipolarScene(spec, 11);
}

// r of one pair with a perturbation h along coordinate k of δ (which = 0), η_first (1) or
// η_second (2).
double Perturbed(const global::EpipolarMotion& motion, const global::BearingPair& pair,
                 const Pose& X, int which, int k, double h) {
  std::array<std::array<double, 6>, 3> d{};
  d[which][k] = h;
  return SampsonResidual<double>(X, motion.hand, pair, d[0].data(), d[1].data(), d[2].data());
}

TEST(EpipolarJacobians, MatchFiniteDifferencesOfTheSampsonResidual) {
  const testing::EpipolarScene scene = NoisyScene();
  const EpipolarJacobians d = DifferentiateEpipolar(scene.problem, scene.X);
  const std::map<int, int> station = EpipolarStationIndex(scene.problem);
  ASSERT_EQ(d.r.size(), 18);
  ASSERT_EQ(d.G.cols(), 6 * int(station.size()));
  const double h = 1e-6;
  int row = 0;
  double largest_residual = 0.0;
  for (const global::EpipolarMotion& motion : scene.problem.motions) {
    const int f = 6 * station.at(motion.first_station);
    const int s = 6 * station.at(motion.second_station);
    for (const global::BearingPair& pair : motion.pairs) {
      EXPECT_NEAR(d.r[row], Perturbed(motion, pair, scene.X, 0, 0, 0.0), 1e-15);
      largest_residual = std::max(largest_residual, std::abs(d.r[row]));
      for (int k = 0; k < 6; ++k) {
        const auto central = [&](int which) {
          return (Perturbed(motion, pair, scene.X, which, k, h) -
                  Perturbed(motion, pair, scene.X, which, k, -h)) /
                 (2 * h);
        };
        EXPECT_NEAR(d.J(row, k), central(0), 1e-6) << "row " << row << ", δ" << k;
        EXPECT_NEAR(d.G(row, f + k), central(1), 1e-6) << "row " << row << ", η_first " << k;
        EXPECT_NEAR(d.G(row, s + k), central(2), 1e-6) << "row " << row << ", η_second " << k;
      }
      ++row;
    }
  }
  EXPECT_GT(largest_residual, 1e-5);  // the noisy rays do not meet exactly
}

TEST(EpipolarJacobians, ColumnsOfStationsOutsideAMotionAreZero) {
  const testing::EpipolarScene scene = NoisyScene();
  const EpipolarJacobians d = DifferentiateEpipolar(scene.problem, scene.X);
  const std::map<int, int> station = EpipolarStationIndex(scene.problem);
  int row = 0;
  for (const global::EpipolarMotion& motion : scene.problem.motions) {
    for (std::size_t p = 0; p < motion.pairs.size(); ++p, ++row) {
      for (const auto& [name, index] : station) {
        if (name != motion.first_station && name != motion.second_station) {
          EXPECT_EQ(d.G.row(row).segment<6>(6 * index).norm(), 0.0);
        }
      }
    }
  }
}

TEST(EpipolarJacobians, SixBearingPairsAreTooFew) {
  testing::EpipolarSceneSpec spec;
  spec.motions = 2;
  spec.pairs = 3;
  const testing::EpipolarScene scene = testing::MakeEpipolarScene(spec, 3);
  EXPECT_THROW(DifferentiateEpipolar(scene.problem, scene.X), DegenerateError);
}

}  // namespace
}  // namespace hecal::estimation::detail
