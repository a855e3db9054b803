// Test support (not installed): rotation matrices as real files hold them — not exactly
// orthonormal — with an answer for their projection onto SO(3) that does not use hecal's.
//
// ControllerMatrix(R, size) is M = R·(I + size·S) with S a fixed symmetric matrix (largest entry
// 1): M = R·P with P = I + size·S symmetric positive definite is M's polar decomposition, so the
// rotation nearest to M in the Frobenius norm is exactly R (Higham, "Computing the polar
// decomposition — with applications", SIAM J. Sci. Stat. Comput. 7(4), 1986, thm. 1).
// so3::OrthonormalityError(M) = max(|P² − I|, |det P − 1|) ≈ 2·size: size = 1e-5 is a robot
// controller's own matrix written with 17 digits (libfranka's O_T_EE is off by 1.9e-5).
// IsNearestRotation checks the same characterisation the other way round, for matrices whose
// rotation is not known (Tabb's 6-decimal prints): R is a rotation and RᵀM is symmetric
// positive definite.
#pragma once

#include <Eigen/Eigenvalues>
#include <cstdio>
#include <string>

namespace hecal::testing {

struct NearlyOrthonormal {
  Eigen::Matrix3d rotation;  // the nearest rotation
  Eigen::Matrix3d matrix;    // what the file holds
};

inline NearlyOrthonormal ControllerMatrix(const Eigen::Matrix3d& R, double size) {
  Eigen::Matrix3d S;
  S << 1.0, 0.3, -0.5, 0.3, -0.8, 0.2, -0.5, 0.2, 0.6;
  return {R, R * (Eigen::Matrix3d::Identity() + size * S)};
}

// Every entry of M, row-major, with 17 significant digits (a double exactly), between separators.
inline std::string Digits17(const Eigen::MatrixXd& M, const std::string& separator) {
  std::string text;
  for (Eigen::Index r = 0; r < M.rows(); ++r) {
    for (Eigen::Index c = 0; c < M.cols(); ++c) {
      char buffer[32];
      std::snprintf(buffer, sizeof(buffer), "%.17g", M(r, c));
      text += (r > 0 || c > 0 ? separator : std::string()) + buffer;
    }
  }
  return text;
}

// The 4×4 homogeneous matrix [M t; 0 0 0 1].
inline Eigen::Matrix4d Homogeneous(const Eigen::Matrix3d& M, const Eigen::Vector3d& t) {
  Eigen::Matrix4d H = Eigen::Matrix4d::Identity();
  H.topLeftCorner<3, 3>() = M;
  H.topRightCorner<3, 1>() = t;
  return H;
}

// True when R is a rotation (within `tolerance`) and RᵀM is symmetric positive definite (its
// antisymmetric part within `tolerance`): then R is the rotation nearest to M.
inline bool IsNearestRotation(const Eigen::Matrix3d& R, const Eigen::Matrix3d& M,
                              double tolerance) {
  const double orthonormal =
      (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  const Eigen::Matrix3d P = R.transpose() * M;
  const double antisymmetric = (P - P.transpose()).cwiseAbs().maxCoeff();
  const Eigen::Matrix3d symmetric = 0.5 * (P + P.transpose());
  const double smallest =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(symmetric, Eigen::EigenvaluesOnly)
          .eigenvalues()
          .minCoeff();
  return orthonormal <= tolerance && R.determinant() > 0.0 && antisymmetric <= tolerance &&
         smallest > 0.0;
}

}  // namespace hecal::testing
