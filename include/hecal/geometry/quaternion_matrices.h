// Quaternion product as a matrix–vector product (thesis appendix A.1, eq. A.1):
//   r * q = Q(r) · q = W(q) · r
// with quaternions as 4-vectors in (w, x, y, z) order and * the Hamilton product.
//   Q(r) = [ r0 −rx −ry −rz ]      W(r) = [ r0 −rx −ry −rz ]
//          [ rx  r0 −rz  ry ]             [ rx  r0  rz −ry ]
//          [ ry  rz  r0 −rx ]             [ ry −rz  r0  rx ]
//          [ rz −ry  rx  r0 ]             [ rz  ry −rx  r0 ]
// Used by Horaud–Dornaika (f1(q) = Σ‖Q(v'_i) q − W(v_i) q‖²) and by the linear pose paper's
// orthogonalisation.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace hecal {

// (w, x, y, z) 4-vector of a quaternion and back. Eigen stores (x, y, z, w): never use coeffs().
inline Eigen::Vector4d ToWxyz(const Eigen::Quaterniond& q) {
  return Eigen::Vector4d(q.w(), q.x(), q.y(), q.z());
}
inline Eigen::Quaterniond FromWxyz(const Eigen::Vector4d& v) {
  return Eigen::Quaterniond(v(0), v(1), v(2), v(3));
}

// Left-multiplication matrix: Q(r) · q = r * q.
Eigen::Matrix4d QuaternionLeftMatrix(const Eigen::Vector4d& r);
// Right-multiplication matrix: W(r) · q = q * r.
Eigen::Matrix4d QuaternionRightMatrix(const Eigen::Vector4d& r);

}  // namespace hecal
