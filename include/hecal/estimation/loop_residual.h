// The residual of one station's pose loop and its analytic Jacobians
// (docs/handeye-methods.md#maximum-likelihood).
//
// Station i measures A_i and B_i with Z = A_i · X · B_i (handeye/problem.h). Its residual is
//        E_i = Z⁻¹ · A_i · X · B_i,        r_i = Log(E_i) ∈ R⁶,  (ω, v) order,
// zero for a perfect fit. With right perturbations X → X·Exp(δX), Z → Z·Exp(δZ)
// (docs/conventions.md):
//   X:  E_i → Z⁻¹ A_i X Exp(δX) B_i = E_i · Exp(Ad(B_i⁻¹) δX)
//   Z:  E_i → Exp(−δZ) E_i          = E_i · Exp(−Ad(E_i⁻¹) δZ)
// and Log(E · Exp(ε)) = r + Jr⁻¹(r) ε + O(ε²), so
//        ∂r_i/∂δX =  Jr⁻¹(r_i) · Ad(B_i⁻¹),        ∂r_i/∂δZ = −Jr⁻¹(r_i) · Ad(E_i⁻¹).
// (Jr⁻¹ is se3::RightJacobianInverse; Barfoot 2017 §7.1.5, Solà et al. 2018 §4.)
//
// LoopCost is the Ceres cost of one station: the whitened residual W_i · r_i (W_i a square root
// of the inverse covariance, station_covariance.h), with two pose parameter blocks X and Z on
// Se3RightManifold (se3_manifold.h) and the lifted Jacobians that manifold expects.
#pragma once

#include <ceres/sized_cost_function.h>

#include "hecal/estimation/se3_manifold.h"
#include "hecal/geometry/types.h"

namespace hecal::estimation {

using Matrix6x12d = Eigen::Matrix<double, 6, 12>;

// r = Log(Z⁻¹ A X B). When jacobian is not null it receives [∂r/∂δX, ∂r/∂δZ] (6 × 12).
Vector6d LoopResidual(const Pose& A, const Pose& B, const Pose& X, const Pose& Z,
                      Matrix6x12d* jacobian = nullptr);

class LoopCost final : public ceres::SizedCostFunction<6, kPoseAmbientSize, kPoseAmbientSize> {
 public:
  // whitening: W with Wᵀ W = Σ⁻¹ (station_covariance.h), or the identity for the plain residual.
  LoopCost(const Pose& A, const Pose& B, const Matrix6d& whitening);

  // Owned by the caller (or by a ceres::Problem with cost-function ownership).
  static ceres::CostFunction* Create(const Pose& A, const Pose& B, const Matrix6d& whitening);

  // parameters[0] = X, parameters[1] = Z (7 ambient doubles each).
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  Pose A_;
  Pose B_;
  Matrix6d whitening_;
};

}  // namespace hecal::estimation
