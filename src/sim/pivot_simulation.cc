#include "hecal/sim/pivot_simulation.h"

#include <numbers>

#include "hecal/core/random_draws.h"
#include "hecal/geometry/so3.h"

namespace hecal::sim {

PivotScene SimulatePivot(const PivotSceneOptions& options, std::mt19937_64& rng) {
  hecal::NormalDistribution lateral(0.0, 0.02);
  hecal::UniformRealDistribution uniform(0.0, 1.0);
  const auto between = [&](double low, double high) { return low + (high - low) * uniform(rng); };
  PivotScene scene;
  scene.tip.x() = lateral(rng);
  scene.tip.y() = lateral(rng);
  scene.tip.z() = between(0.1, 0.25);
  scene.pivot = {between(0.4, 0.8), between(-0.3, 0.3), between(0.0, 0.3)};
  const Eigen::Matrix3d down =
      Eigen::AngleAxisd(std::numbers::pi, Eigen::Vector3d::UnitX()).toRotationMatrix();
  NoiseModel noise;
  noise.rotation_sigma = options.rotation_sigma;
  noise.translation_sigma = options.translation_sigma;
  for (int i = 0; i < options.stations; ++i) {
    const Eigen::Vector3d omega(between(-options.max_tilt, options.max_tilt),
                                between(-options.max_tilt, options.max_tilt),
                                between(-options.max_tilt, options.max_tilt));
    const Eigen::Matrix3d R = down * so3::Exp(omega);
    const Pose T = MakePose(R, scene.pivot - R * scene.tip);
    scene.exact.push_back(T);
    scene.T_base_flange.push_back(AddNoise(T, noise, rng));
  }
  return scene;
}

}  // namespace hecal::sim
