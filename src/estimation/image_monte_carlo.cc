#include "hecal/estimation/image_monte_carlo.h"

#include "hecal/geometry/se3.h"
#include "hecal/uncertainty/monte_carlo.h"

namespace hecal::estimation {

CalibrationCovariance ImageMonteCarloCovariance(const std::vector<Pose>& T_base_gripper,
                                                const std::vector<ImagePoints>& images,
                                                const ReprojectionResult& estimate,
                                                const ReprojectionOptions& options,
                                                const CovarianceOptions& covariance) {
  ReprojectionOptions fixed = options;
  fixed.pixel_sigma = estimate.pixel_sigma;
  fixed.robot_sigma = estimate.robot_sigma;
  fixed.estimate_robot_sigma = false;
  if (options.refine_intrinsics) fixed.camera = estimate.camera;
  Eigen::Index points = 0;
  for (const ImagePoints& image : images) points += static_cast<Eigen::Index>(image.pixels.size());
  const Eigen::Index robot_dim = 6 * static_cast<Eigen::Index>(T_base_gripper.size());
  const int dim = static_cast<int>(robot_dim + 2 * points);
  Vector6d robot_sd;
  robot_sd << Eigen::Vector3d::Constant(estimate.robot_sigma.rotation),
      Eigen::Vector3d::Constant(estimate.robot_sigma.translation);

  uncertainty::MonteCarloOptions mc;
  mc.samples = covariance.samples;
  mc.seed = covariance.seed;
  mc.threads = covariance.threads;
  auto sample = [&](int k) -> std::vector<Pose> {
    const Eigen::VectorXd z = uncertainty::StandardNormalSample(mc.seed, k, dim);
    std::vector<Pose> robot = T_base_gripper;
    for (size_t i = 0; i < robot.size(); ++i) {
      const Eigen::Index at = 6 * static_cast<Eigen::Index>(i);
      robot[i] = robot[i] * se3::Exp(robot_sd.cwiseProduct(z.segment<6>(at)));
    }
    std::vector<ImagePoints> noisy = images;
    Eigen::Index at = robot_dim;
    for (ImagePoints& image : noisy) {
      for (Eigen::Vector2d& pixel : image.pixels) {
        pixel += estimate.pixel_sigma * z.segment<2>(at);
        at += 2;
      }
    }
    const ReprojectionResult refined =
        RefineReprojection(robot, noisy, estimate.X, estimate.Z, fixed);
    return {refined.X, refined.Z};
  };
  return FromMonteCarlo(uncertainty::MonteCarloSamples<std::vector<Pose>>(
      sample, std::vector<Pose>{estimate.X, estimate.Z}, mc));
}

}  // namespace hecal::estimation
