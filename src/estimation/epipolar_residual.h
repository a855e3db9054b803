// The angular Sampson residual of one bearing pair of the target-free problem as a function of
// the perturbations of X and of the two hand poses (used by epipolar_polish.cc,
// epipolar_jacobians.cc and epipolar_robot_noise.cc; not installed). Notation as in
// global/epipolar_problem.h.
//
//   r = v·(R_A u × t_A) / sqrt(|P_v (R_A u × t_A)|² + |P_u R_Aᵀ(t_A × v)|²),   P_x = I − x xᵀ,
//
// the epipolar triple product over its first-order standard deviation when each ray is turned
// isotropically in its tangent plane by one radian: r has the ray noise's standard deviation
// (radians) whatever the geometry. Perturbations, each a 6-vector (ω, τ) applied on the right
// as (Exp(ω), τ) — to first order the right perturbation Exp(ω, τ) of docs/conventions.md:
//   X = X̂ (Exp(ω), τ),  H_first = Ĥ_first (Exp(ω_f), τ_f),  H_second = Ĥ_second (Exp(ω_s), τ_s),
// so the hand motion is B = (Exp(ω_f), τ_f)⁻¹ B̂ (Exp(ω_s), τ_s).
#pragma once

#include <ceres/rotation.h>

#include <Eigen/Core>

#include "hecal/geometry/types.h"
#include "hecal/global/epipolar_problem.h"

namespace hecal::estimation::detail {

template <typename T>
using Vec3 = Eigen::Matrix<T, 3, 1>;
template <typename T>
using Mat3 = Eigen::Matrix<T, 3, 3>;

// The rotation and translation of (Exp(ω), τ) for δ = (ω, τ); identity when delta is null.
template <typename T>
void SmallPose(const T* delta, Mat3<T>* R, Vec3<T>* t) {
  if (delta == nullptr) {
    R->setIdentity();
    t->setZero();
    return;
  }
  ceres::AngleAxisToRotationMatrix(delta, ceres::ColumnMajorAdapter3x3(R->data()));
  *t = Vec3<T>(delta[3], delta[4], delta[5]);
}

// X̂ (Exp(ω), τ) for δ = (ω, τ).
inline Pose ApplyDelta(const Pose& X0, const double* delta) {
  Mat3<double> E;
  Vec3<double> tau;
  SmallPose(delta, &E, &tau);
  return MakePose(X0.linear() * E, X0.translation() + X0.linear() * tau);
}

// r for the pair under X̂ and B̂ perturbed by delta (X), eta_first and eta_second (hand poses;
// null: unperturbed).
template <typename T>
T SampsonResidual(const Pose& X0, const Pose& B0, const global::BearingPair& pair, const T* delta,
                  const T* eta_first, const T* eta_second) {
  Mat3<T> E_x, E_f, E_s;
  Vec3<T> tau_x, tau_f, tau_s;
  SmallPose(delta, &E_x, &tau_x);
  SmallPose(eta_first, &E_f, &tau_f);
  SmallPose(eta_second, &E_s, &tau_s);
  const Mat3<T> R = X0.linear().cast<T>() * E_x;
  const Vec3<T> t = X0.translation().cast<T>() + X0.linear().cast<T>() * tau_x;
  // B = P_f⁻¹ B̂ P_s with P = (E, τ): rotation E_fᵀ R̂_B E_s, translation E_fᵀ(R̂_B τ_s + t̂_B − τ_f).
  const Mat3<T> R_B = E_f.transpose() * B0.linear().cast<T>() * E_s;
  const Vec3<T> t_B =
      E_f.transpose() * (B0.linear().cast<T>() * tau_s + B0.translation().cast<T>() - tau_f);
  const Mat3<T> R_A = R.transpose() * R_B * R;
  const Vec3<T> t_A = R.transpose() * (R_B * t + t_B - t);
  const Vec3<T> u = pair.second.normalized().cast<T>();
  const Vec3<T> v = pair.first.normalized().cast<T>();
  const Vec3<T> g_v = (R_A * u).cross(t_A);
  const Vec3<T> g_u = R_A.transpose() * t_A.cross(v);
  const Vec3<T> p_v = g_v - v * v.dot(g_v);
  const Vec3<T> p_u = g_u - u * u.dot(g_u);
  using std::sqrt;
  const T scale = sqrt(p_v.squaredNorm() + p_u.squaredNorm() + T(1e-300));
  return v.dot(g_v) / scale;
}

}  // namespace hecal::estimation::detail
