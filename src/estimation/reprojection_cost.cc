#include "hecal/estimation/reprojection_cost.h"

#include "hecal/geometry/se3.h"
#include "hecal/geometry/skew.h"

namespace hecal::estimation {
namespace {

using Matrix3x6d = Eigen::Matrix<double, 3, 6>;

// [A  B] as a 3×6 block.
Matrix3x6d Columns(const Eigen::Matrix3d& A, const Eigen::Matrix3d& B) {
  Matrix3x6d M;
  M << A, B;
  return M;
}

// Writes a tangent Jacobian (rows × 6) into Ceres' ambient layout (rows × 7, last column 0).
template <int Rows>
void Lift(const Eigen::Matrix<double, Rows, 6>& tangent, double* ambient) {
  Eigen::Map<Eigen::Matrix<double, Rows, kPoseAmbientSize, Eigen::RowMajor>> out(ambient);
  out.template leftCols<6>() = tangent;
  out.col(6).setZero();
}

}  // namespace

Pose CameraFromUnknowns(handeye::Setup setup, const Pose& X, const Pose& Z,
                        const Pose& T_base_gripper) {
  const Pose A_inverse =
      setup == handeye::Setup::kEyeInHand ? T_base_gripper.inverse() : T_base_gripper;
  return X.inverse() * A_inverse * Z;
}

ReprojectionCost::ReprojectionCost(handeye::Setup setup, const pose::CameraModel& camera,
                                   const Eigen::Vector3d& point_target,
                                   const Eigen::Vector2d& pixel, double pixel_sigma)
    : setup_(setup),
      camera_(camera),
      point_(point_target),
      pixel_(pixel),
      inverse_sigma_(1.0 / pixel_sigma) {}

bool ReprojectionCost::Evaluate(double const* const* parameters, double* residuals,
                                double** jacobians) const {
  const Pose X = PoseFromParameters(parameters[0]);
  const Pose Z = PoseFromParameters(parameters[1]);
  const Pose G = PoseFromParameters(parameters[2]);
  const pose::CameraModel camera = pose::WithIntrinsics(camera_, parameters[3]);
  const Pose B = CameraFromUnknowns(setup_, X, Z, G);
  const Eigen::Vector3d p = B * point_;
  if (!(p.z() > 0.0)) return false;
  Eigen::Matrix<double, 2, 3> J_pi;
  const bool want = jacobians != nullptr;
  const Eigen::Vector2d u = pose::Project(camera, p, want ? &J_pi : nullptr);
  Eigen::Map<Eigen::Vector2d> residual(residuals);
  residual = inverse_sigma_ * (u - pixel_);
  if (!want) return true;

  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  const Eigen::Matrix<double, 2, 3> J = inverse_sigma_ * J_pi;
  if (jacobians[0] != nullptr) {
    const Matrix3x6d dp = Columns(Skew(p), -I);
    Lift<2>(J * dp, jacobians[0]);
  }
  if (jacobians[1] != nullptr) {
    const Matrix3x6d dp = B.linear() * Columns(-Skew(point_), I);
    Lift<2>(J * dp, jacobians[1]);
  }
  if (jacobians[2] != nullptr) {
    Matrix3x6d dp;
    if (setup_ == handeye::Setup::kEyeInHand) {
      const Eigen::Vector3d w = G.inverse() * (Z * point_);
      dp = X.linear().transpose() * Columns(Skew(w), -I);
    } else {
      const Eigen::Vector3d y = Z * point_;
      dp = X.linear().transpose() * G.linear() * Columns(-Skew(y), I);
    }
    Lift<2>(J * dp, jacobians[2]);
  }
  if (jacobians[3] != nullptr) {
    Eigen::Map<Eigen::Matrix<double, 2, pose::kNumIntrinsics, Eigen::RowMajor>> J_intrinsics(
        jacobians[3]);
    J_intrinsics = inverse_sigma_ * pose::ProjectionIntrinsicsJacobian(camera, p);
  }
  return true;
}

RobotPosePriorCost::RobotPosePriorCost(const Pose& measured, double rotation_sigma,
                                       double translation_sigma)
    : measured_inverse_(measured.inverse()) {
  weight_ << Eigen::Vector3d::Constant(1.0 / rotation_sigma),
      Eigen::Vector3d::Constant(1.0 / translation_sigma);
}

bool RobotPosePriorCost::Evaluate(double const* const* parameters, double* residuals,
                                  double** jacobians) const {
  const Vector6d r = se3::Log(measured_inverse_ * PoseFromParameters(parameters[0]));
  Eigen::Map<Vector6d> residual(residuals);
  residual = weight_.asDiagonal() * r;
  if (jacobians != nullptr && jacobians[0] != nullptr) {
    const Matrix6d J = weight_.asDiagonal() * se3::RightJacobianInverse(r);
    Lift<6>(J, jacobians[0]);
  }
  return true;
}

}  // namespace hecal::estimation
