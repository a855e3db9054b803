#include "hecal/global/local_start.h"

#include <Eigen/SVD>
#include <cmath>

#include "hecal/geometry/nearest_rotation.h"
#include "hecal/geometry/so3.h"
#include "hecal/global/cube_feasibility.h"
#include "hecal/global/essential_matrix.h"

namespace hecal::global {

std::optional<Pose> LocalStart(const EpipolarProblem& problem, double translation_bound) {
  constexpr double kMinHandAngle = M_PI / 180;
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
  int used = 0;
  for (const EpipolarMotion& motion : problem.motions) {
    const Eigen::Vector3d beta = so3::Log(motion.hand.linear());
    if (beta.norm() < kMinHandAngle) continue;
    const auto R_A = RotationFromEssential(motion.pairs);
    if (!R_A) continue;
    M += beta * so3::Log(*R_A).transpose();
    ++used;
  }
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(M);
  if (used < 2 || svd.singularValues()[1] <= 1e-9 * svd.singularValues()[0]) return std::nullopt;
  return BestTranslation(problem, NearestRotationSvd(M), translation_bound, M_PI / 2, 30).X;
}

FixedRotationFit BestTranslation(const EpipolarProblem& problem, const Eigen::Matrix3d& R,
                                 double translation_bound, double high, int iterations,
                                 const Eigen::Vector3d& hint) {
  CubeQuery query{so3::Log(R), 0.0, 0.0, translation_bound};
  FixedRotationFit fit;
  fit.X = MakePose(R, hint);
  fit.error = MaxRayError(problem, fit.X);
  double low = 0.0;
  Eigen::Vector3d start = hint;
  for (int iteration = 0; iteration < iterations; ++iteration) {
    query.epsilon = 0.5 * (low + high);
    const auto t = TestCube(problem, query, start, &fit.lps);
    if (!t) {
      low = query.epsilon;
      continue;
    }
    high = query.epsilon;
    start = *t;
    const Pose X = MakePose(R, *t);
    const double error = MaxRayError(problem, X);
    if (error < fit.error) {
      fit.error = error;
      fit.X = X;
    }
  }
  return fit;
}

}  // namespace hecal::global
