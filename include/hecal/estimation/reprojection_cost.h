// The reprojection error of one target point seen at one station, as a function of the hand–eye
// unknowns X, Z and the station's robot pose G = T_base_gripper (the image-level counterpart of
// loop_residual.h).
//
// The camera pose of station i follows from the model Z = A_i · X · B_i (handeye/problem.h):
//        T_camera_target_i = B_i = X⁻¹ · A_i⁻¹ · Z,
//   eye-in-hand  A_i = G_i    → B_i = X⁻¹ · G_i⁻¹ · Z
//   eye-to-hand  A_i = G_i⁻¹  → B_i = X⁻¹ · G_i · Z
// and a target point P (target frame, metres) projects to u = π(B_i · P) with the camera model π
// (pose/camera_model.h). Residual: r = (π(B_i P) − u_measured) / σ_px  (2 rows, whitened).
//
// Analytic Jacobians, right perturbations T → T·Exp(ε), ε = (ω, v) (docs/conventions.md), with
// p = B_i P the point in the camera frame and J_π = ∂π/∂p (2 × 3):
//   X:  B → Exp(−ε) B                       ∂p/∂ε = [ [p]×   −I ]
//   Z:  B → B Exp(ε)                         ∂p/∂ε = R_B [ −[P]×  I ]
//   G (eye-in-hand, w = G⁻¹ Z P):  B → X⁻¹ Exp(−ε) G⁻¹ Z
//                                            ∂p/∂ε = R_Xᵀ [ [w]×   −I ]
//   G (eye-to-hand, y = Z P):      B → X⁻¹ G Exp(ε) Z
//                                            ∂p/∂ε = R_Xᵀ R_G [ −[y]×  I ]
// and ∂r/∂ε = J_π ∂p/∂ε / σ_px. The blocks are on Se3RightManifold (se3_manifold.h), which
// expects these tangent Jacobians "lifted" into the first six of seven ambient columns.
// A fourth block holds the intrinsics (pose::IntrinsicsOf order: fx, fy, cx, cy, k1, k2, p1, p2,
// k3); ∂r/∂k = pose::ProjectionIntrinsicsJacobian / σ_px. Hold it constant to keep the camera
// model fixed.
// A point behind the camera (z ≤ 0) makes Evaluate return false, so Ceres rejects the step.
#pragma once

#include <ceres/sized_cost_function.h>

#include <Eigen/Core>

#include "hecal/estimation/se3_manifold.h"
#include "hecal/geometry/types.h"
#include "hecal/handeye/problem.h"
#include "hecal/pose/camera_model.h"

namespace hecal::estimation {

// T_camera_target of a station from the unknowns (see above).
Pose CameraFromUnknowns(handeye::Setup setup, const Pose& X, const Pose& Z,
                        const Pose& T_base_gripper);

class ReprojectionCost final
    : public ceres::SizedCostFunction<2, kPoseAmbientSize, kPoseAmbientSize, kPoseAmbientSize,
                                      pose::kNumIntrinsics> {
 public:
  // parameters: X, Z, G (7 ambient doubles each), the intrinsics (9). `camera` gives the image
  // size only; its intrinsics are the fourth block's.
  ReprojectionCost(handeye::Setup setup, const pose::CameraModel& camera,
                   const Eigen::Vector3d& point_target, const Eigen::Vector2d& pixel,
                   double pixel_sigma);

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  handeye::Setup setup_;
  pose::CameraModel camera_;
  Eigen::Vector3d point_;
  Eigen::Vector2d pixel_;
  double inverse_sigma_;
};

// The prior on a measured robot pose: r = W · Log(G_measured⁻¹ · G), W = diag(1/σ_rot ×3,
// 1/σ_trans ×3); ∂r/∂ε = W · Jr⁻¹(Log(G_measured⁻¹ G)) (se3::RightJacobianInverse).
class RobotPosePriorCost final : public ceres::SizedCostFunction<6, kPoseAmbientSize> {
 public:
  RobotPosePriorCost(const Pose& measured, double rotation_sigma, double translation_sigma);

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  Pose measured_inverse_;
  Vector6d weight_;
};

}  // namespace hecal::estimation
