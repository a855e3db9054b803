#include "hecal/sim/noise.h"

#include <gtest/gtest.h>

#include <cmath>

#include "hecal/geometry/se3.h"

namespace hecal::sim {
namespace {

TEST(Noise, GaussianHasTheRequestedStandardDeviationPerComponent) {
  std::mt19937_64 rng(1);
  NoiseModel model{NoiseModel::Kind::kGaussian, 0.02, 0.003};
  const int n = 20000;
  Vector6d sum = Vector6d::Zero(), sum_sq = Vector6d::Zero();
  for (int i = 0; i < n; ++i) {
    const Vector6d d = SamplePerturbation(model, rng);
    sum += d;
    sum_sq += d.cwiseProduct(d);
  }
  for (int k = 0; k < 6; ++k) {
    const double sigma = k < 3 ? 0.02 : 0.003;
    EXPECT_NEAR(sum(k) / n, 0.0, 4.0 * sigma / std::sqrt(n));
    EXPECT_NEAR(std::sqrt(sum_sq(k) / n), sigma, 0.03 * sigma);
  }
}

TEST(Noise, UniformStaysWithinPlusMinusSigma) {
  std::mt19937_64 rng(2);
  NoiseModel model{NoiseModel::Kind::kUniform, 0.01, 0.002};
  double max_rotation = 0.0;
  for (int i = 0; i < 5000; ++i) {
    const Vector6d d = SamplePerturbation(model, rng);
    EXPECT_LE(d.head<3>().cwiseAbs().maxCoeff(), 0.01);
    EXPECT_LE(d.tail<3>().cwiseAbs().maxCoeff(), 0.002);
    max_rotation = std::max(max_rotation, d.head<3>().cwiseAbs().maxCoeff());
  }
  EXPECT_GT(max_rotation, 0.0099);
}

TEST(Noise, SystematicIsTheSameOffsetEveryTime) {
  std::mt19937_64 rng(3);
  NoiseModel model{NoiseModel::Kind::kSystematic, 0.01, 0.002};
  const Pose T = se3::Exp((Vector6d() << 0.3, -0.2, 0.1, 1.0, 2.0, 3.0).finished());
  const Pose a = AddNoise(T, model, rng);
  const Pose b = AddNoise(T, model, rng);
  EXPECT_LT((a.matrix() - b.matrix()).norm(), 1e-15);
  const Vector6d delta = se3::Log(T.inverse() * a);
  EXPECT_LT((delta - (Vector6d() << 0.01, 0.01, 0.01, 0.002, 0.002, 0.002).finished()).norm(),
            1e-12);
}

TEST(Noise, ParsesKindNames) {
  EXPECT_EQ(ParseNoiseKind("uniform"), NoiseModel::Kind::kUniform);
  EXPECT_EQ(NoiseKindName(NoiseModel::Kind::kSystematic), "systematic");
  EXPECT_FALSE(ParseNoiseKind("normal").has_value());
}

}  // namespace
}  // namespace hecal::sim
