// Test support (not installed): rigid motions built from their screw geometry, written
// independently of src/geometry, for its tests to compare against (Chasles' theorem: every rigid
// motion is a rotation θ about a line and a slide d along it; docs/handeye-methods.md#daniilidis).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <numbers>
#include <random>

#include "hecal/core/random_draws.h"
#include "hecal/geometry/types.h"
#include "testing/random_poses.h"

namespace hecal::testing {

// The line through c with unit direction n, the angle θ about it and the slide d along it.
struct ScrewLine {
  Eigen::Vector3d n;
  Eigen::Vector3d c;
  double theta = 0.0;
  double d = 0.0;
};

// n uniform on the sphere, c ~ N(0, I), θ uniform on [min_theta, max_theta), d ~ N(0, 1), drawn
// in this order.
inline ScrewLine RandomScrewLine(std::mt19937_64& rng, double min_theta = 0.0,
                                 double max_theta = std::numbers::pi) {
  ScrewLine line;
  line.n = RandomUnitVector(rng);
  line.c = RandomGaussianVector(rng);
  line.theta = hecal::UniformRealDistribution(min_theta, max_theta)(rng);
  line.d = RandomGaussianVector(rng).x();
  return line;
}

// Rotate θ about the line through c along n, then translate d along n: x ↦ c + R(x − c) + d n.
inline Pose ScrewMotion(const Eigen::Vector3d& n, const Eigen::Vector3d& c, double theta,
                        double d) {
  const Eigen::Matrix3d R = Eigen::AngleAxisd(theta, n).toRotationMatrix();
  return MakePose(R, c - R * c + d * n);
}

inline Pose ScrewMotion(const ScrewLine& line) {
  return ScrewMotion(line.n, line.c, line.theta, line.d);
}

}  // namespace hecal::testing
