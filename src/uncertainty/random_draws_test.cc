// hecal/core/random_draws.h against libstdc++'s distributions: the same bits for the same engine
// state, for both engine widths, with a kept second normal draw and across the rounding to 1.
#include "hecal/core/random_draws.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <random>

namespace hecal {
namespace {

bool SameBits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

template <class Engine>
void ExpectNormalMatches(std::uint64_t seed, double mean, double stddev) {
  Engine ours_engine(seed);
  Engine std_engine(seed);
  NormalDistribution ours(mean, stddev);
  std::normal_distribution<double> reference(mean, stddev);
  for (int i = 0; i < 100000; ++i) {
    const double a = ours(ours_engine);
    const double b = reference(std_engine);
    ASSERT_TRUE(SameBits(a, b)) << "draw " << i << ": " << a << " vs " << b;
  }
  EXPECT_EQ(ours_engine, std_engine);  // the same number of engine outputs consumed
}

template <class Engine>
void ExpectUniformMatches(std::uint64_t seed, double a, double b) {
  Engine ours_engine(seed);
  Engine std_engine(seed);
  const UniformRealDistribution ours(a, b);
  std::uniform_real_distribution<double> reference(a, b);
  for (int i = 0; i < 100000; ++i) {
    const double x = ours(ours_engine);
    const double y = reference(std_engine);
    ASSERT_TRUE(SameBits(x, y)) << "draw " << i << ": " << x << " vs " << y;
    ASSERT_GE(x, a);
    ASSERT_LT(x, b);
  }
  EXPECT_EQ(ours_engine, std_engine);
}

TEST(RandomDraws, NormalGivesTheStandardLibrarysBits) {
  ExpectNormalMatches<std::mt19937_64>(7, 0.0, 1.0);
  ExpectNormalMatches<std::mt19937_64>(2024, -3.5, 0.01);
  ExpectNormalMatches<std::mt19937>(11, 1.0, 2.5);
}

TEST(RandomDraws, UniformGivesTheStandardLibrarysBits) {
  ExpectUniformMatches<std::mt19937_64>(3, -1.0, 1.0);
  ExpectUniformMatches<std::mt19937_64>(5, 0.2, 5.0);
  ExpectUniformMatches<std::mt19937>(13, -400.0, 400.0);
}

TEST(RandomDraws, ResetForgetsTheKeptDrawLikeTheStandardLibrary) {
  std::mt19937_64 ours_engine(17);
  std::mt19937_64 std_engine(17);
  NormalDistribution ours;
  std::normal_distribution<double> reference;
  for (int i = 0; i < 101; ++i) {
    ASSERT_TRUE(SameBits(ours(ours_engine), reference(std_engine)));
    if (i % 3 == 0) {
      ours.reset();
      reference.reset();
    }
  }
  EXPECT_EQ(ours_engine, std_engine);
}

// An engine whose every output is the maximum: the canonical sum rounds to 1 and both clamp it
// to the largest double below 1.
struct MaximumEngine {
  using result_type = std::uint64_t;
  static constexpr result_type min() { return 0; }
  static constexpr result_type max() { return ~result_type{0}; }
  result_type operator()() { return max(); }
};

TEST(RandomDraws, RoundingToOneGivesTheLargestDoubleBelowOne) {
  MaximumEngine engine;
  EXPECT_EQ(CanonicalUniform(engine), std::nextafter(1.0, 0.0));
  const double standard = std::generate_canonical<double, 53>(engine);
  EXPECT_EQ(standard, std::nextafter(1.0, 0.0));
}

}  // namespace
}  // namespace hecal
