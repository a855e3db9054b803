// The per-station error of Strobl & Hirzinger's SE(3) metric (K. H. Strobl, G. Hirzinger,
// "Optimal Hand-Eye Calibration", IEEE/RSJ IROS 2006, §III;
// docs/handeye-methods.md#strobl-and-hirzinger) on the absolute-pose loop of station i, M_i = A_i ·
// X · B_i, which should equal Z (handeye/problem.h).
//
// The discrepancy between M_i and Z can be seen from either end of the loop:
//   target end:  E_i = Z⁻¹ · M_i   (translation t_E: displacement of the target origin)
//   base end:    D_i = M_i · Z⁻¹   (translation t_D: displacement of the base origin)
// Both have the same rotation angle θ_i = |Log(R_E)| = arccos((tr R_E − 1)/2), but the
// translations differ (a rotation error moves the far end by its lever arm), so the
// translation error is not frame-invariant; Strobl & Hirzinger combine both ends. hecal uses
// the quadratic mean of the two ends,
//        tra_i² = (|t_E|² + |t_D|²) / 2,       rot_i² = θ_i² = |ω_i|²,  ω_i = Log(R_E),
// (the square of the arithmetic mean up to (|t_E| − |t_D|)²/4, and unlike it smooth at zero,
// which a Gauss–Newton solver needs), and the cost
//        Υ = Σ_i rot_i² / σ_rot² + tra_i² / σ_tra².
// As a 9-vector residual: e_i = [ω_i / σ_rot;  t_E / (√2 σ_tra);  t_D / (√2 σ_tra)], |e_i|² = Υ_i.
//
// Jacobians (right perturbations X·Exp(δX), Z·Exp(δZ); see loop_residual.h):
//   E_i → E_i · Exp(Γ^E δ),  Γ^E_X = Ad(B_i⁻¹),       Γ^E_Z = −Ad(E_i⁻¹)
//   D_i → D_i · Exp(Γ^D δ),  Γ^D_X = Ad(Z · B_i⁻¹),   Γ^D_Z = −Ad(Z)
//   ∂ω/∂δ = Jr⁻¹(ω) [I 0] Γ^E,   ∂t_E/∂δ = R_E [0 I] Γ^E,   ∂t_D/∂δ = R_D [0 I] Γ^D.
#pragma once

#include <ceres/sized_cost_function.h>

#include "hecal/estimation/se3_manifold.h"
#include "hecal/geometry/types.h"

namespace hecal::estimation {

using Vector9d = Eigen::Matrix<double, 9, 1>;
using Matrix9x12d = Eigen::Matrix<double, 9, 12>;

// Unweighted e_i = [ω; t_E/√2; t_D/√2] (so rot² = |e.head(3)|², tra² = |e.tail(6)|²) and, when
// jacobian is not null, ∂e/∂(δX, δZ).
Vector9d StroblResidual(const Pose& A, const Pose& B, const Pose& X, const Pose& Z,
                        Matrix9x12d* jacobian = nullptr);

// Ceres cost of one station: [ω/σ_rot; t_E/(√2σ_tra); t_D/(√2σ_tra)], parameters X and Z on
// Se3RightManifold (lifted Jacobians, se3_manifold.h).
class StroblCost final : public ceres::SizedCostFunction<9, kPoseAmbientSize, kPoseAmbientSize> {
 public:
  StroblCost(const Pose& A, const Pose& B, double sigma_rotation, double sigma_translation);
  static ceres::CostFunction* Create(const Pose& A, const Pose& B, double sigma_rotation,
                                     double sigma_translation);
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  Pose A_;
  Pose B_;
  Vector9d weights_;
};

}  // namespace hecal::estimation
