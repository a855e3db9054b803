#include "hecal/handeye/minimal_solution.h"

#include <cmath>

#include "hecal/geometry/rotation.h"
#include "hecal/geometry/so3.h"
#include "hecal/handeye/observability.h"

namespace hecal::handeye {
namespace {

// The orthonormal frame (ŝ, d̂, ŝ × d̂) of two unit vectors u, v: ŝ ∥ u + v, d̂ ∥ u − v.
Eigen::Matrix3d BisectorFrame(const Eigen::Vector3d& u, const Eigen::Vector3d& v) {
  Eigen::Matrix3d frame;
  frame.col(0) = (u + v).normalized();
  frame.col(1) = (u - v).normalized();
  frame.col(2) = frame.col(0).cross(frame.col(1));
  return frame;
}

// Unit axes of two rotations, or false when either turns by less than kMinRotation or the axes
// are within kParallelAxes of parallel.
bool UnitAxes(const Eigen::Matrix3d& R_1, const Eigen::Matrix3d& R_2, Eigen::Vector3d* axis_1,
              Eigen::Vector3d* axis_2) {
  const Eigen::Vector3d omega_1 = so3::Log(R_1), omega_2 = so3::Log(R_2);
  const double angle_1 = omega_1.norm(), angle_2 = omega_2.norm();
  if (!(angle_1 >= kMinRotation && angle_2 >= kMinRotation)) return false;
  *axis_1 = omega_1 / angle_1;
  *axis_2 = omega_2 / angle_2;
  return axis_1->cross(*axis_2).norm() >= std::sin(kParallelAxes);
}

}  // namespace

std::optional<Solution> SolveMinimal(const Problem& problem, size_t a, size_t b, size_t c) {
  // Rotations of the motions M_j = A_j⁻¹ · A_a and N_j = B_j · B_a⁻¹, j = b, c.
  const Eigen::Matrix3d& R_Aa = problem.A[a].linear();
  const Eigen::Matrix3d R_Ba_inverse = problem.B[a].linear().transpose();
  Eigen::Vector3d alpha[2], beta[2];
  if (!UnitAxes(problem.A[b].linear().transpose() * R_Aa, problem.A[c].linear().transpose() * R_Aa,
                &alpha[0], &alpha[1]) ||
      !UnitAxes(problem.B[b].linear() * R_Ba_inverse, problem.B[c].linear() * R_Ba_inverse,
                &beta[0], &beta[1])) {
    return std::nullopt;
  }
  const Eigen::Matrix3d R_X =
      BisectorFrame(alpha[0], alpha[1]) * BisectorFrame(beta[0], beta[1]).transpose();

  // Translations: R_Ai · t_X − t_Z = −t_Ai − R_Ai · R_X · t_Bi for the three stations, by
  // their 6 × 6 normal equations.
  Eigen::Matrix<double, 6, 6> normal = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> right = Eigen::Matrix<double, 6, 1>::Zero();
  Eigen::Vector4d quaternion_sum = Eigen::Vector4d::Zero();
  for (size_t i : {a, b, c}) {
    const Eigen::Matrix3d& R_A = problem.A[i].linear();
    const Eigen::Vector3d rhs =
        -problem.A[i].translation() - R_A * (R_X * problem.B[i].translation());
    normal.topRightCorner<3, 3>() -= R_A.transpose();
    right.head<3>() += R_A.transpose() * rhs;
    right.tail<3>() -= rhs;
    // Z's rotation: R_Ai · R_X · R_Bi as a quaternion, signs aligned with the sum.
    Eigen::Vector4d q = QuaternionFromMatrix(R_A * R_X * problem.B[i].linear()).coeffs();
    if (q.dot(quaternion_sum) < 0.0) q = -q;
    quaternion_sum += q;
  }
  normal.topLeftCorner<3, 3>() = 3.0 * Eigen::Matrix3d::Identity();
  normal.bottomRightCorner<3, 3>() = 3.0 * Eigen::Matrix3d::Identity();
  normal.bottomLeftCorner<3, 3>() = normal.topRightCorner<3, 3>().transpose();
  const Eigen::Matrix<double, 6, 1> t = normal.ldlt().solve(right);
  const Eigen::Quaterniond mean(Eigen::Vector4d(quaternion_sum.normalized()));
  Solution solution;
  solution.X = MakePose(R_X, t.head<3>());
  solution.Z = MakePose(MatrixFromQuaternion(mean), t.tail<3>());
  return solution;
}

}  // namespace hecal::handeye
