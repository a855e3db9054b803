// Test support (not installed): seeded random rotations and poses, and the edge cases every
// geometry property test must cover (identity, exactly π about each axis, tiny angles, near π).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "hecal/core/random_draws.h"
#include "hecal/geometry/types.h"

namespace hecal::testing {

// Uniform on SO(3): a normalised 4-D Gaussian is uniform on S³ (Shoemake's argument).
// The helpers below draw components last to first: the order the tests' data were generated in.
inline Eigen::Matrix3d RandomRotation(std::mt19937_64& rng) {
  hecal::NormalDistribution normal;
  const double z = normal(rng);
  const double y = normal(rng);
  const double x = normal(rng);
  const double w = normal(rng);
  const Eigen::Quaterniond q(w, x, y, z);
  return q.normalized().toRotationMatrix();
}

// Each component N(0, sigma²).
inline Eigen::Vector3d RandomGaussianVector(std::mt19937_64& rng, double sigma = 1.0) {
  hecal::NormalDistribution normal(0.0, sigma);
  const double z = normal(rng);
  const double y = normal(rng);
  const double x = normal(rng);
  return Eigen::Vector3d(x, y, z);
}

inline Eigen::Vector3d RandomUnitVector(std::mt19937_64& rng) {
  hecal::NormalDistribution normal;
  const double z = normal(rng);
  const double y = normal(rng);
  const double x = normal(rng);
  return Eigen::Vector3d(x, y, z).normalized();
}

// Rotation vector with the given angle about a random axis.
inline Eigen::Vector3d RandomRotationVector(std::mt19937_64& rng, double angle) {
  return angle * RandomUnitVector(rng);
}

// A point uniform in the cube [−half_side, half_side]³.
inline Eigen::Vector3d RandomPointInBox(std::mt19937_64& rng, double half_side) {
  hecal::UniformRealDistribution uniform(-half_side, half_side);
  const double z = uniform(rng);
  const double y = uniform(rng);
  const double x = uniform(rng);
  return Eigen::Vector3d(x, y, z);
}

// Random pose: uniform rotation, translation uniform in [−scale, scale]³ (metres).
inline Pose RandomPose(std::mt19937_64& rng, double scale = 1.0) {
  const Eigen::Vector3d translation = RandomPointInBox(rng, scale);  // drawn first
  return MakePose(RandomRotation(rng), translation);
}

// Rotation vectors at the edges of the domain: zero, 1e-9 rad, 1e-4 rad, exactly π about each
// axis and about a diagonal, π − 1e-9, π − 1e-6 and 1e-2 / 0.1 (series thresholds) about
// random axes.
inline std::vector<Eigen::Vector3d> EdgeCaseRotationVectors(std::mt19937_64& rng) {
  constexpr double pi = std::numbers::pi;
  std::vector<Eigen::Vector3d> cases = {
      Eigen::Vector3d::Zero(),         pi * Eigen::Vector3d::UnitX(),
      pi * Eigen::Vector3d::UnitY(),   pi * Eigen::Vector3d::UnitZ(),
      -pi * Eigen::Vector3d::UnitZ(),  pi * Eigen::Vector3d(1, 1, 1).normalized(),
      1e-9 * Eigen::Vector3d::UnitX(),
  };
  for (double angle :
       {1e-12, 1e-9, 1e-6, 1e-4, 1e-2, 0.1, pi / 2, pi - 1e-2, pi - 1e-6, pi - 1e-9, pi}) {
    for (int i = 0; i < 3; ++i) cases.push_back(RandomRotationVector(rng, angle));
  }
  return cases;
}

// The twist (ω, v): rotation first, as geometry/se3.h orders the tangent.
inline Vector6d Twist(const Eigen::Vector3d& omega, const Eigen::Vector3d& v) {
  Vector6d xi;
  xi << omega, v;
  return xi;
}

// `count` twists with |ω| uniform in [0, max_angle) about a random axis and v ~ N(0, I), then one
// per EdgeCaseRotationVectors entry, v ~ N(0, I).
inline std::vector<Vector6d> RandomTwists(std::mt19937_64& rng, int count, double max_angle) {
  hecal::UniformRealDistribution angle(0.0, max_angle);
  std::vector<Vector6d> twists;
  for (int i = 0; i < count; ++i) {
    const Eigen::Vector3d v = RandomGaussianVector(rng);  // drawn first
    const Eigen::Vector3d omega = RandomRotationVector(rng, angle(rng));
    twists.push_back(Twist(omega, v));
  }
  for (const Eigen::Vector3d& omega : EdgeCaseRotationVectors(rng)) {
    twists.push_back(Twist(omega, RandomGaussianVector(rng)));
  }
  return twists;
}

// ω = θ n with |ω| on the requested side of `threshold` (below: |ω| < threshold), within a few
// ulps of it, so a test can evaluate both branches of a piecewise formula (a series below a
// threshold, the closed form above) at (almost) one point.
inline Eigen::Vector3d RotationVectorAtThreshold(const Eigen::Vector3d& n, double threshold,
                                                 bool below) {
  double theta = threshold;
  Eigen::Vector3d omega = theta * n;
  while ((omega.norm() < threshold) != below) {
    theta = std::nextafter(theta, below ? 0.0 : 1.0);
    omega = theta * n;
  }
  return omega;
}

}  // namespace hecal::testing
