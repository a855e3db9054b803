#include "hecal/estimation/bound.h"

#include <Eigen/Cholesky>
#include <cmath>
#include <stdexcept>

#include "fixed_size_kernels.h"
#include "hecal/core/error.h"
#include "hecal/estimation/loop_residual.h"
#include "hecal/estimation/station_covariance.h"

namespace hecal::estimation {
namespace {

using Matrix12d = Eigen::Matrix<double, 12, 12>;

// I = Σ_i J_iᵀ Σ_i⁻¹ J_i (header).
Matrix12d Information(const handeye::Problem& truth, const Pose& X, const Pose& Z,
                      const std::vector<Matrix6d>& robot, const std::vector<Matrix6d>& camera) {
  if (robot.size() != truth.A.size() || camera.size() != truth.A.size()) {
    throw std::invalid_argument("FirstOrderBound: one robot and one camera covariance per station");
  }
  Matrix12d information = Matrix12d::Zero();
  for (size_t i = 0; i < truth.A.size(); ++i) {
    information += StationInformation(truth.setup, truth.A[i], truth.B[i], X, Z, robot[i],
                                      camera[i]);
  }
  return information;
}

AccuracyBound BoundFrom(const Matrix12d& covariance) {
  AccuracyBound bound;
  bound.covariance = covariance;
  bound.rotation_rmse_X = std::sqrt(covariance.block<3, 3>(0, 0).trace());
  bound.translation_rmse_X = std::sqrt(covariance.block<3, 3>(3, 3).trace());
  bound.rotation_rmse_Z = std::sqrt(covariance.block<3, 3>(6, 6).trace());
  bound.translation_rmse_Z = std::sqrt(covariance.block<3, 3>(9, 9).trace());
  return bound;
}

}  // namespace

Eigen::Matrix<double, 12, 12> StationInformation(handeye::Setup setup, const Pose& A,
                                                 const Pose& B, const Pose& X, const Pose& Z,
                                                 const Matrix6d& robot, const Matrix6d& camera) {
  Matrix6x12d J;
  LoopResidual(A, B, X, Z, &J);
  const Matrix6d W = WhiteningMatrix(StationCovariance(setup, A, B, X, robot, camera));
  Matrix12d information = Matrix12d::Zero();
  internal::AddWeightedGram(W.lazyProduct(J), 1.0, &information);
  return information;
}

AccuracyBound FirstOrderBound(const handeye::Problem& truth, const Pose& X, const Pose& Z,
                              const std::vector<Matrix6d>& robot,
                              const std::vector<Matrix6d>& camera) {
  const Matrix12d information = Information(truth, X, Z, robot, camera);
  const Eigen::LDLT<Matrix12d> ldlt(information);
  const double smallest = ldlt.vectorD().minCoeff();
  if (ldlt.info() != Eigen::Success || !(smallest > 1e-12 * ldlt.vectorD().maxCoeff())) {
    throw DegenerateError("X and Z to first order (the information matrix is singular)",
                          "use stations whose rotations turn about at least two axes");
  }
  return BoundFrom(ldlt.solve(Matrix12d::Identity()));
}

AccuracyBound FirstOrderBound(const handeye::Problem& truth, const Pose& X, const Pose& Z,
                              const PoseSigma& robot_sigma, const PoseSigma& camera_sigma,
                              const handeye::FixedTranslation& fixed) {
  const size_t n = truth.A.size();
  const Matrix12d information =
      Information(truth, X, Z, std::vector<Matrix6d>(n, PoseCovariance(robot_sigma)),
                  std::vector<Matrix6d>(n, PoseCovariance(camera_sigma)));
  return BoundFrom(handeye::ConstrainedInverse(information, {X, Z}, fixed));
}

AccuracyBound FirstOrderBound(const handeye::Problem& truth, const Pose& X, const Pose& Z,
                              const PoseSigma& robot_sigma, const PoseSigma& camera_sigma) {
  return FirstOrderBound(truth, X, Z,
                         std::vector<Matrix6d>(truth.A.size(), PoseCovariance(robot_sigma)),
                         std::vector<Matrix6d>(truth.A.size(), PoseCovariance(camera_sigma)));
}

}  // namespace hecal::estimation
