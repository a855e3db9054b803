// The normalised direct linear transform (DLT): the classical linear baseline for pose from known
// points, next to the linear pose paper's method (linear_pose.h). Two paths, chosen by the object's
// shape:
//
// Projective path (object points not coplanar, N ≥ 6) — Hartley & Zisserman, "Multiple View
// Geometry", 2nd ed., §7.1 (algorithm 7.1) with the normalisation of §4.4.4:
//   1. Normalise: image points x̃ = s₂(x − c₂) (mean distance √2 from the origin), object points
//      X̃ = s₃(X − c₃) (mean distance √3); the similarities are T₂, T₃.
//   2. Each point gives two rows of A (2N × 12): [X̃ₕᵀ 0 −x̃ X̃ₕᵀ], [0 X̃ₕᵀ −ỹ X̃ₕᵀ],
//      X̃ₕ = (X̃, 1).
//      p̃ (the 3×4 matrix P̃ row-major) is A's last right singular vector (an SVD of A itself,
//      not of AᵀA: noise-free data then give the pose to ~1e-12 instead of ~1e-8).
//   3. Denormalise P = T₂⁻¹ P̃ T₃ = λ [R | t] (the image points are normalised coordinates, so the
//      camera matrix is the identity). The sign of λ makes the depth of the object's centroid
//      positive; |λ| is the mean singular value of P's left 3×3 block M.
//   4. R = the nearest rotation to M/λ (NearestRotationSvd), t = p₄/λ.
//
// Planar path (object points coplanar, N ≥ 4) — the homography of Zhang, "A Flexible New
// Technique for Camera Calibration", IEEE TPAMI 22(11), 2000, §2.2 and appendix A with K = I:
//   1. Plane frame: origin at the centroid c, axes e₁, e₂ in the least-squares plane and
//      n = e₁ × e₂ (AnalyseSpread), plane coordinates q = (e₁·(X − c), e₂·(X − c)).
//   2. Normalised DLT of the homography H (2N × 9, both point sets normalised as above):
//      x ∝ H (q, 1).
//   3. H = λ [r₁ r₂ t']: λ = (‖h₁‖ + ‖h₂‖)/2 with the sign that puts the centroid in front of the
//      camera (t'_z > 0); R' = nearest rotation to [h₁ h₂ h₁×h₂/λ]/λ, t' = h₃/λ.
//   4. Back to the target frame: R = R' [e₁ e₂ n]ᵀ, t = t' − R c.
//
// Which path: coplanar when σ3 ≤ options.planarity_tolerance · σ1 of the centred object points
// (PointSpread). The default 1e-3 sends nearly flat objects to the homography: there the
// projective system's smallest singular values are within the pixel noise, while the plane model
// errs by at most the flatness, which the refinement (pose_refinement.h) removes.
//
// Inputs: normalised image coordinates (F = 1, DltPoseNormalized) or pixels and a camera
// (DltPose undistorts them first). Units: object points in any length unit; t in the same unit.
// Errors: InputError for mismatched or non-finite inputs (CheckCorrespondences); DegenerateError
// for fewer than 6 points off a plane or 4 on one, collinear object points, "a plane plus one
// point" (the plane fixes 8 of P's 11 degrees of freedom and the point 2: LonePointOffAPlane in
// linear_pose.h), or a linear system whose null space is not one-dimensional (e.g. 3 of 4
// coplanar points on a line): the second-smallest singular value of A below 1e-6 of the largest.
#pragma once

#include <Eigen/Core>
#include <string_view>
#include <vector>

#include "hecal/geometry/types.h"
#include "hecal/pose/camera_model.h"

namespace hecal::pose {

enum class DltPath { kProjective, kHomography };
// "projective DLT" | "homography".
std::string_view DltPathName(DltPath path);

struct DltPoseOptions {
  // Coplanar (→ homography) when σ3 ≤ planarity_tolerance · σ1 (see above).
  double planarity_tolerance = 1e-3;  // in (0, 1)

  // core/options_check.h: false naming DltPoseOptions.planarity_tolerance outside (0, 1).
  bool IsValid(std::string* why) const;
};

struct DltPoseResult {
  Pose T_camera_target = Pose::Identity();
  DltPath path = DltPath::kProjective;
};

// From normalised image coordinates (x_k, y_k) = (x_c/z_c, y_c/z_c).
DltPoseResult DltPoseNormalized(const std::vector<Eigen::Vector3d>& object_points,
                                const std::vector<Eigen::Vector2d>& normalized,
                                const DltPoseOptions& options = {});

// From pixels: undistorts them with `camera` (UndistortPoints), then DltPoseNormalized.
DltPoseResult DltPose(const std::vector<Eigen::Vector3d>& object_points,
                      const std::vector<Eigen::Vector2d>& pixels, const CameraModel& camera,
                      const DltPoseOptions& options = {});

}  // namespace hecal::pose
