#include "hecal/estimation/station_covariance.h"

#include <Eigen/Cholesky>

#include "fixed_size_kernels.h"
#include "hecal/core/error.h"
#include "hecal/geometry/se3.h"
#include "hecal/geometry/skew.h"

namespace hecal::estimation {
namespace {

// P_rot = diag(1,1,1,0,0,0) and P_trans = diag(0,0,0,1,1,1) sandwiched: J P Jᵀ.
Matrix6d Sandwich(const Matrix6d& J, int block) {
  const Eigen::Matrix<double, 6, 3> columns = J.middleCols<3>(3 * block);
  return columns * columns.transpose();
}

Matrix6d DiagonalBlock(int block) {
  Matrix6d P = Matrix6d::Zero();
  P.block<3, 3>(3 * block, 3 * block).setIdentity();
  return P;
}

}  // namespace

Matrix6d RobotNoiseJacobian(handeye::Setup setup, const Pose& A, const Pose& B, const Pose& X) {
  if (setup == handeye::Setup::kEyeInHand) return se3::Adjoint((X * B).inverse());
  return -se3::Adjoint((A * X * B).inverse());
}

NoiseComponents StationNoiseComponents(handeye::Setup setup, const Pose& A, const Pose& B,
                                       const Pose& X) {
  const Matrix6d J = RobotNoiseJacobian(setup, A, B, X);
  NoiseComponents Q;
  Q[kRobotRotation] = Sandwich(J, 0);
  Q[kRobotTranslation] = Sandwich(J, 1);
  Q[kCameraRotation] = DiagonalBlock(0);
  Q[kCameraTranslation] = DiagonalBlock(1);
  const Eigen::Matrix3d R = B.linear();
  Q[kCameraTiltExcess].setZero();
  Q[kCameraTiltExcess].topLeftCorner<3, 3>() =
      R.transpose() * Eigen::Vector3d(1.0, 1.0, 0.0).asDiagonal() * R;
  Q[kCameraDepthExcess].setZero();
  Q[kCameraDepthExcess].bottomRightCorner<3, 3>() = R.row(2).transpose() * R.row(2);
  return Q;
}

Matrix6d CombineComponents(const NoiseComponents& components, const NoiseVariances& variances) {
  Matrix6d sigma = Matrix6d::Zero();
  // A variance of zero (the camera excess of the isotropic model) adds nothing: skipped.
  for (int k = 0; k < kNumNoiseComponents; ++k)
    if (variances[k] != 0.0) sigma += variances[k] * components[k];
  return sigma;
}

Matrix6d StationCovarianceOf(handeye::Setup setup, const Pose& A, const Pose& B, const Pose& X,
                             const NoiseVariances& variances) {
  const Pose T = setup == handeye::Setup::kEyeInHand ? Pose(X * B) : Pose(A * X * B);
  const Eigen::Vector3d u = T.inverse().translation();
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  const double robot_rotation = variances[kRobotRotation];
  Matrix6d sigma;
  sigma.topLeftCorner<3, 3>() = (robot_rotation + variances[kCameraRotation]) * identity;
  sigma.topRightCorner<3, 3>() = -robot_rotation * Skew(u);
  sigma.bottomLeftCorner<3, 3>() = robot_rotation * Skew(u);
  sigma.bottomRightCorner<3, 3>() =
      robot_rotation * (u.squaredNorm() * identity - u * u.transpose()) +
      (variances[kRobotTranslation] + variances[kCameraTranslation]) * identity;
  const Eigen::Matrix3d R = B.linear();
  if (variances[kCameraTiltExcess] != 0.0) {
    sigma.topLeftCorner<3, 3>() += variances[kCameraTiltExcess] * R.transpose() *
                                   Eigen::Vector3d(1.0, 1.0, 0.0).asDiagonal() * R;
  }
  if (variances[kCameraDepthExcess] != 0.0) {
    sigma.bottomRightCorner<3, 3>() +=
        variances[kCameraDepthExcess] * R.row(2).transpose() * R.row(2);
  }
  return sigma;
}

NoiseVariances Variances(const PoseSigma& robot, const PoseSigma& camera,
                         const PoseSigma& camera_excess) {
  return {robot.rotation * robot.rotation,
          robot.translation * robot.translation,
          camera.rotation * camera.rotation,
          camera.translation * camera.translation,
          camera_excess.rotation * camera_excess.rotation,
          camera_excess.translation * camera_excess.translation};
}

Matrix6d StationCovariance(handeye::Setup setup, const Pose& A, const Pose& B, const Pose& X,
                           const Matrix6d& robot, const Matrix6d& camera) {
  const Matrix6d J = RobotNoiseJacobian(setup, A, B, X);
  return J * robot * J.transpose() + camera;
}

Matrix6d StationCovariance(handeye::Setup setup, const Pose& A, const Pose& B, const Pose& X,
                           const PoseSigma& robot, const PoseSigma& camera) {
  return StationCovariance(setup, A, B, X, PoseCovariance(robot), PoseCovariance(camera));
}

Matrix6d WhiteningMatrix(const Matrix6d& covariance) {
  const Eigen::LLT<Matrix6d> llt(covariance);
  if (llt.info() != Eigen::Success || !(llt.matrixLLT().diagonal().array() > 0.0).all()) {
    throw DegenerateError(
        "a station's noise: its covariance is not positive definite (a rotation or translation "
        "sigma of zero, or one so far below the other that the two cannot be weighed together)",
        "give --robot-sigma and --camera-sigma with a non-zero rotation and translation each");
  }
  return internal::LowerTriangularInverse(llt.matrixLLT());
}

}  // namespace hecal::estimation
