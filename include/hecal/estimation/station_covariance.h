// First-order covariance of a station's residual r_i = Log(Z⁻¹ A_i X B_i) (loop_residual.h) from
// the robot and camera measurement noise (pose_sigma.h), and the whitening that turns r_i into
// a vector of independent unit-variance components.
//
// Noise (docs/conventions.md, right perturbations): the robot reports G̃_i = G_i · Exp(δg),
// G = T_base_gripper, δg ~ N(0, Σ_g); the camera reports B̃_i = B_i · Exp(δc), δc ~ N(0, Σ_c).
//  - camera:  E_i → E_i · Exp(δc)                                  ⇒ ∂r/∂δc = Jr⁻¹(r_i)
//  - robot, eye-in-hand (A_i = G_i):
//             E_i → Z⁻¹ G_i Exp(δg) X B_i = E_i · Exp(Ad((X B_i)⁻¹) δg)
//                                                                   ⇒ ∂r/∂δg = Jr⁻¹(r_i) Ad((X
//                                                                   B_i)⁻¹)
//  - robot, eye-to-hand (A_i = G_i⁻¹, so the noise enters on the LEFT of A_i: Ã_i = Exp(−δg) A_i):
//             E_i → Z⁻¹ Exp(−δg) A_i X B_i = E_i · Exp(−Ad((A_i X B_i)⁻¹) δg)
//                                                                   ⇒ ∂r/∂δg = −Jr⁻¹(r_i) Ad((A_i X
//                                                                   B_i)⁻¹)
// (X B_i = T_gripper_target and A_i X B_i ≈ Z = T_gripper_target are the target pose seen from
// the flange: a rotation error of the robot moves the target by the lever arm |t|, which is why
// robot rotation noise dominates the translation residuals.)
// First order at r_i = 0 (Jr⁻¹ → I; the neglected factor is 1 + O(|r_i|)):
//        Σ_i = J_g Σ_g J_gᵀ + Σ_c,    J_g = ±Ad(T_i),  T_i = (X B_i)⁻¹ | (A_i X B_i)⁻¹,
// which depends on X and the measurements only. With Σ_g = diag(σ_gr² I, σ_gt² I) and
// Σ_c = diag(σ_cr² I, σ_ct² I) it is linear in the four variances:
//        Σ_i = σ_gr² Q_i[kRobotRotation] + σ_gt² Q_i[kRobotTranslation]
//            + σ_cr² Q_i[kCameraRotation] + σ_ct² Q_i[kCameraTranslation],
// which is the form the variance-component estimator (noise_estimation.h) works with.
//
// Anisotropic camera noise. A camera pose from PnP on a planar target is least precise in the
// target's tilt (rotation about the camera's x and y axes) and in its depth (translation along
// the optical axis z); its spin about z and its lateral position are precise. Two more
// components describe an excess of the camera noise along those axes, in the camera frame, on
// top of the isotropic part: the camera reports R̃ = Exp(ω) R_B, t̃ = t_B + v with
// ω ~ N(0, σ_tilt² diag(1, 1, 0)) and v ~ N(0, σ_depth² diag(0, 0, 1)) (the shape sim/noise.h
// draws for "pnp"), so in the right perturbation of B (rotation R_Bᵀ ω, translation R_Bᵀ v):
//        Q_i[kCameraTiltExcess]  = blockdiag(R_Bᵀ diag(1, 1, 0) R_B, 0)
//        Q_i[kCameraDepthExcess] = blockdiag(0, R_Bᵀ diag(0, 0, 1) R_B).
// Their variances are zero unless the anisotropic noise model is chosen (noise_estimation.h).
#pragma once

#include <array>

#include "hecal/estimation/pose_sigma.h"
#include "hecal/geometry/types.h"
#include "hecal/handeye/problem.h"

namespace hecal::estimation {

enum NoiseComponent {
  kRobotRotation = 0,
  kRobotTranslation = 1,
  kCameraRotation = 2,
  kCameraTranslation = 3,
  kCameraTiltExcess = 4,   // rotation about the camera's x and y axes (see above)
  kCameraDepthExcess = 5,  // translation along the camera's z axis
};
inline constexpr int kNumNoiseComponents = 6;

using NoiseComponents = std::array<Matrix6d, kNumNoiseComponents>;
using NoiseVariances = std::array<double, kNumNoiseComponents>;  // σ², indexed by NoiseComponent

// ∂r_i/∂δg at r_i = 0 (see above).
Matrix6d RobotNoiseJacobian(handeye::Setup setup, const Pose& A, const Pose& B, const Pose& X);

// The unit-variance components Q_i[k] of station (A, B) at the estimate X.
NoiseComponents StationNoiseComponents(handeye::Setup setup, const Pose& A, const Pose& B,
                                       const Pose& X);

// Σ_i = Σ_k variances[k] · components[k].
Matrix6d CombineComponents(const NoiseComponents& components, const NoiseVariances& variances);

// CombineComponents(StationNoiseComponents(setup, A, B, X), variances) in closed form, for the
// ml solver's whitening at every re-weighting. With the robot-noise Jacobian ±Ad(T⁻¹), T = X B
// (eye-in-hand) or A X B (eye-to-hand), and u the translation of T⁻¹, its rotation and
// translation columns give J_r J_rᵀ = [[I, −u^], [u^, −u^ u^]] and J_t J_tᵀ = [[0, 0], [0, I]]
// (the rotation of T⁻¹ cancels), so
//   Σ_i = [[(θ_rr + θ_cr) I + θ_tilt Q_tilt, −θ_rr u^], [θ_rr u^, θ_rr (|u|² I − u uᵀ) +
//          (θ_rt + θ_ct) I + θ_depth Q_depth]]
// with Q_tilt, Q_depth the 3 × 3 blocks of the camera's excess components above.
Matrix6d StationCovarianceOf(handeye::Setup setup, const Pose& A, const Pose& B, const Pose& X,
                             const NoiseVariances& variances);

// The variances of robot and camera noise and the camera's tilt / depth excess (rotation /
// translation fields; zero: the isotropic model).
NoiseVariances Variances(const PoseSigma& robot, const PoseSigma& camera,
                         const PoseSigma& camera_excess = {});

// Σ_i = J_g Σ_g J_gᵀ + Σ_c for a robot covariance Σ_g (of T_base_gripper as measured, whatever
// the setup) and a camera covariance Σ_c (of T_camera_target), both 6 × 6 right perturbations,
// any shape (e.g. the Student-t model's per-station scales or the camera's tilt / depth excess).
Matrix6d StationCovariance(handeye::Setup setup, const Pose& A, const Pose& B, const Pose& X,
                           const Matrix6d& robot, const Matrix6d& camera);

// The same for isotropic sigmas (PoseCovariance, pose_sigma.h).
Matrix6d StationCovariance(handeye::Setup setup, const Pose& A, const Pose& B, const Pose& X,
                           const PoseSigma& robot, const PoseSigma& camera);

// W = L⁻¹ with Σ = L Lᵀ (Cholesky), so |W r|² = rᵀ Σ⁻¹ r and W r has unit covariance.
// Throws DegenerateError when Σ is not positive definite (e.g. a σ of zero): the noise model the
// data would be weighed with.
Matrix6d WhiteningMatrix(const Matrix6d& covariance);

}  // namespace hecal::estimation
