#include "hecal/streams/pose_stream.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "hecal/core/error.h"
#include "hecal/core/random_draws.h"
#include "hecal/geometry/so3.h"

namespace hecal::streams {
namespace {

using ::testing::HasSubstr;

// A motion quadratic in t in the tangent space: R(t) = Exp(ω t + ½ α t²), p(t) = p₀ + v t + ½ a t².
Pose Motion(double t) {
  const Eigen::Vector3d omega(0.3, -0.2, 0.5), alpha(0.1, 0.05, -0.2);
  const Eigen::Vector3d p0(0.1, 0.2, 0.3), v(0.05, -0.1, 0.02), a(0.3, 0.1, -0.2);
  return MakePose(so3::Exp(omega * t + 0.5 * alpha * t * t), p0 + v * t + 0.5 * a * t * t);
}

PoseStream Sampled(double rate, double duration, double noise = 0.0, unsigned seed = 1) {
  std::mt19937_64 rng(seed);
  hecal::NormalDistribution normal(0.0, noise);
  PoseStream stream;
  stream.source = "s.csv";
  for (int k = 0; k * (1.0 / rate) <= duration; ++k) {
    const double t = k / rate;
    Pose T = Motion(t);
    if (noise > 0) {
      // Drawn last to first: the order these tests' data were generated in.
      const double wz = normal(rng), wy = normal(rng), wx = normal(rng);
      T.linear() = T.linear() * so3::Exp(Eigen::Vector3d(wx, wy, wz));
      const double tz = normal(rng), ty = normal(rng), tx = normal(rng);
      T.translation() += Eigen::Vector3d(tx, ty, tz);
    }
    stream.stamps.push_back(t);
    stream.poses.push_back(T);
    stream.lines.push_back(k + 2);
  }
  return stream;
}

double PoseError(const Pose& a, const Pose& b) {
  return so3::Log(a.linear().transpose() * b.linear()).norm() +
         (a.translation() - b.translation()).norm();
}

TEST(PoseStream, RejectsBadStampsNamingTheLine) {
  PoseStream stream = Sampled(10, 1);
  stream.stamps[3] = stream.stamps[2];
  try {
    CheckStream(stream);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 5);
    EXPECT_THAT(e.what(), HasSubstr("repeats"));
  }
  stream = Sampled(10, 1);
  stream.stamps[4] = 0.05;
  EXPECT_THROW(CheckStream(stream), InputError);
  stream = Sampled(10, 1);
  stream.stamps[1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(CheckStream(stream), InputError);
  stream = Sampled(10, 0.05);  // one sample
  EXPECT_THROW(CheckStream(stream), InputError);
  EXPECT_NO_THROW(CheckStream(Sampled(10, 1)));
}

TEST(PoseStream, InterpolatesOnTheGeodesicAndNeverAcrossAGap) {
  const PoseStream stream = Sampled(50, 2);
  EXPECT_NEAR(MedianPeriod(stream), 0.02, 1e-12);
  // Between samples the geodesic of SO(3) × R³: at the samples exact, in between close to the
  // smooth motion (second order in the 20 ms period).
  EXPECT_LT(PoseError(*PoseAt(stream, 0.4, 1.0), Motion(0.4)), 1e-12);
  EXPECT_LT(PoseError(*PoseAt(stream, 0.41, 1.0), Motion(0.41)), 1e-4);
  EXPECT_FALSE(PoseAt(stream, -0.01, 1.0));
  EXPECT_FALSE(PoseAt(stream, 2.01, 1.0));
  EXPECT_TRUE(PoseAt(stream, 2.0, 1.0));
  // A gap of 0.02 s is too long for a bound of 0.01 s.
  EXPECT_FALSE(PoseAt(stream, 0.41, 0.01));
}

TEST(PoseStream, SmoothedPoseReproducesQuadraticMotionAndAveragesNoise) {
  const PoseStream clean = Sampled(50, 2);
  for (double t : {0.3, 0.31, 0.333, 1.5}) {
    const std::optional<Pose> T = SmoothPoseAt(clean, t, 0.1, 0.1);
    ASSERT_TRUE(T);
    // Exact for translation; the rotation's tangent coordinates are quadratic only to first
    // order about the nearest sample.
    EXPECT_LT((T->translation() - Motion(t).translation()).norm(), 1e-12);
    EXPECT_LT(so3::Log(T->linear().transpose() * Motion(t).linear()).norm(), 1e-6);
  }
  EXPECT_FALSE(SmoothPoseAt(clean, 0.01, 0.1, 0.1));  // one sample before t
  // With noise: the smoothed poses are closer to the truth than the geodesic's, and their error
  // does not swing with the sample phase (the geodesic's is smallest mid-period).
  const PoseStream noisy = Sampled(50, 20, 1e-3);
  double smooth2 = 0, geodesic2 = 0;
  int n = 0;
  for (double t = 1.0; t < 19.0; t += 0.0137, ++n) {
    smooth2 += std::pow(
        (SmoothPoseAt(noisy, t, 0.1, 0.1)->translation() - Motion(t).translation()).norm(), 2);
    geodesic2 +=
        std::pow((PoseAt(noisy, t, 0.1)->translation() - Motion(t).translation()).norm(), 2);
  }
  EXPECT_LT(smooth2, 0.5 * geodesic2);
  EXPECT_GT(n, 1000);
}

// The factor against the smoothed poses' own spread: many noisy recordings of one motion, the
// smoothed position's error at fixed times, its RMS per axis over the noise per sample.
TEST(PoseStream, SmoothingNoiseFactorIsTheSmoothedPosesSpread) {
  const double sigma = 1e-3;
  for (const double t : {0.5, 0.513, 0.5299}) {
    const double factor = *SmoothingNoiseFactor(Sampled(50, 1), t, 0.1, 0.1);
    // 9–10 samples inside ±0.1 s with tricube weights under a quadratic: about 0.5.
    EXPECT_GT(factor, 0.35);
    EXPECT_LT(factor, 0.7);
    double sum2 = 0;
    const int recordings = 3000;
    for (int r = 0; r < recordings; ++r) {
      const PoseStream noisy = Sampled(50, 1, sigma, static_cast<unsigned>(r + 7));
      sum2 +=
          (SmoothPoseAt(noisy, t, 0.1, 0.1)->translation() - Motion(t).translation()).squaredNorm();
    }
    const double measured = std::sqrt(sum2 / (3.0 * recordings)) / sigma;
    EXPECT_NEAR(measured, factor, 0.04 * factor) << t;  // 9000 draws: ±1.5% (1σ)
  }
  EXPECT_FALSE(SmoothingNoiseFactor(Sampled(50, 1), 0.01, 0.1, 0.1));
}

TEST(PoseStream, SpeedOverABaseline) {
  const PoseStream stream = Sampled(100, 2);
  const std::optional<Speed> speed = SpeedAt(stream, 0.0 + 0.5, 0.1, 0.05);
  ASSERT_TRUE(speed);
  // At t = 0.5 the rotation vector's rate is ω + α t (a first-order approximation of the angular
  // speed when the axis turns slowly); the linear speed |v + a t|.
  const Eigen::Vector3d omega =
      Eigen::Vector3d(0.3, -0.2, 0.5) + 0.5 * Eigen::Vector3d(0.1, 0.05, -0.2);
  const Eigen::Vector3d velocity =
      Eigen::Vector3d(0.05, -0.1, 0.02) + 0.5 * Eigen::Vector3d(0.3, 0.1, -0.2);
  EXPECT_NEAR(speed->angular, omega.norm(), 0.02);
  EXPECT_NEAR(speed->linear, velocity.norm(), 1e-3);
  EXPECT_FALSE(SpeedAt(stream, 0.02, 0.1, 0.05));  // t − baseline is before the stream
}

}  // namespace
}  // namespace hecal::streams
