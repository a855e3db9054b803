// Uniform and Gaussian draws that give the same bits as libstdc++'s std::uniform_real_distribution
// <double> and std::normal_distribution<double> for the same engine state, with any compiler.
//
// Why our own: both libstdc++ distributions draw through std::generate_canonical, which computes
// log(2^64) / log(2) in long double on every call. GCC folds that constant; clang (hecal's default
// compiler, docs/build.md) does not, and a normal draw then costs ~200 ns instead of ~15 ns —
// most of the time of the Monte Carlo studies, the renderers' pixel noise and the simulators.
// The algorithms below are the ones libstdc++ uses, so every seeded result (simulate, plan,
// studies, test data) is unchanged:
//  - a canonical uniform in [0, 1): k = ceil(53 / log2(R)) engine outputs u_j (R the engine's
//    range, 2^64 for std::mt19937_64, 2^32 for std::mt19937) summed as Σ u_j R^j / R^k, and the
//    largest double below 1 when rounding reaches 1;
//  - uniform in [a, b): canonical · (b − a) + a;
//  - normal: Marsaglia's polar method (Marsaglia and Bray, "A convenient method for generating
//    normal variables", SIAM Review 6(3), 1964), two draws per accepted pair, the second kept
//    for the next call.
// Tested bit for bit against the standard library in src/uncertainty/random_draws_test.cc.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

namespace hecal {

// A uniform double in [0, 1) from `engine`, as std::generate_canonical<double, 53>.
template <class Engine>
double CanonicalUniform(Engine& engine) {
  static_assert(Engine::min() == 0, "engines with a non-zero minimum are not supported");
  constexpr std::uint64_t kMax = Engine::max();
  static_assert(kMax == std::numeric_limits<std::uint64_t>::max() ||
                    kMax == std::numeric_limits<std::uint32_t>::max(),
                "engines of 32 or 64 bits only");
  double value = 0.0;
  if constexpr (kMax == std::numeric_limits<std::uint64_t>::max()) {
    value = static_cast<double>(engine()) * 0x1.0p-64;
  } else {
    const double low = static_cast<double>(engine());
    const double high = static_cast<double>(engine()) * 0x1.0p32;
    value = (low + high) * 0x1.0p-64;
  }
  if (value >= 1.0) value = std::nextafter(1.0, 0.0);
  return value;
}

// std::uniform_real_distribution<double>'s draw: uniform in [a, b).
class UniformRealDistribution {
 public:
  explicit UniformRealDistribution(double a = 0.0, double b = 1.0) : a_(a), b_(b) {}

  template <class Engine>
  double operator()(Engine& engine) const {
    return CanonicalUniform(engine) * (b_ - a_) + a_;
  }

  double a() const { return a_; }
  double b() const { return b_; }

 private:
  double a_;
  double b_;
};

// std::normal_distribution<double>'s draw: mean + stddev · N(0, 1).
class NormalDistribution {
 public:
  explicit NormalDistribution(double mean = 0.0, double stddev = 1.0)
      : mean_(mean), stddev_(stddev) {}

  template <class Engine>
  double operator()(Engine& engine) {
    double standard = 0.0;
    if (saved_available_) {
      saved_available_ = false;
      standard = saved_;
    } else {
      double x = 0.0;
      double y = 0.0;
      double r2 = 0.0;
      do {
        x = 2.0 * CanonicalUniform(engine) - 1.0;
        y = 2.0 * CanonicalUniform(engine) - 1.0;
        r2 = x * x + y * y;
      } while (r2 > 1.0 || r2 == 0.0);
      const double multiplier = std::sqrt(-2.0 * std::log(r2) / r2);
      saved_ = x * multiplier;
      saved_available_ = true;
      standard = y * multiplier;
    }
    return standard * stddev_ + mean_;
  }

  // Forgets the kept second draw of a pair (std::normal_distribution::reset).
  void reset() { saved_available_ = false; }

  double mean() const { return mean_; }
  double stddev() const { return stddev_; }

 private:
  double mean_;
  double stddev_;
  double saved_ = 0.0;
  bool saved_available_ = false;
};

}  // namespace hecal
