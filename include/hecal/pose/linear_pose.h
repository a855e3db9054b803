// The linear pose from known points (docs/pose-from-points.md#the-linear-method; "A simple
// algorithm for determining the position and the orientation of rigid bodies basing on visual
// information", Silesian Univ. of Technology, eqs. 8–32).
//
// Given object points P_k (target frame) and their normalised image coordinates (x_k, y_k) —
// pixels undistorted by the camera model, so the paper's pinhole X = F x/z holds with F = 1 —
// find T_camera_target = [R | T], x_c = R P + T:
//   0. Re-origin the object at a reference point P_ref, the first point (the paper's P1; "the
//      number of the point does not matter", section 4): P'_k = P_k − P_ref. Its pose [R | T']
//      has T' = T + R P_ref.
//   1. T' lies on the ray of P_ref: T' = a (x_ref, y_ref, 1), a > 0 its depth (eq. 11).
//   2. For every other point (eqs. 14–15):
//        a (x_k − x_ref) = r1·P'_k − x_k (r3·P'_k),   a (y_k − y_ref) = r2·P'_k − y_k (r3·P'_k),
//      stacked as a B = U R_vec, U 2(N−1)×9 with rows [P'_kᵀ 0 −x_k P'_kᵀ], [0 P'_kᵀ −y_k P'_kᵀ],
//      R_vec = (r11 … r33) row-major (eqs. 16–19).
//   3. Least squares R_vec = a (UᵀU)⁻¹ Uᵀ B = a g (eq. 20), computed as g = U⁺ B by an SVD of U
//      (the same estimate, without squaring U's condition number); the scale from ‖R‖_F² = 3:
//      a = √3 / ‖g‖ (eqs. 21–23), so R_vec = a g and T' = a (x_ref, y_ref, 1) (eqs. 24–26).
//   4. Orthogonalise: R = the rotation nearest to the estimate, by the paper's quaternion
//      eigenvector (eqs. 27–32; NearestRotationQuaternion). Then T = T' − R P_ref.
// The translation is not re-estimated after step 4 (the paper's method); pose_refinement.h
// improves both.
//
// Preconditions, checked: as many image points as object points, all finite; N ≥ 6 (U needs
// 2(N−1) ≥ 9 rows); object points not coplanar (a coplanar set makes U rank deficient: the
// components of R_vec along the plane normal are unobservable). Coplanar means σ3 ≤
// options.planarity_tolerance · σ1 for the singular values σ1 ≥ σ2 ≥ σ3 of the centred object
// points. Violations throw hecal::DegenerateError saying that the linear method needs at least 6
// non-coplanar points and naming the methods that accept the data (ippe / dlt for planar
// targets, dlt / sqpnp for fewer points).
//
// Degenerate configurations and the choice of P_ref ("a P1 whose ray makes the system
// ill-conditioned"). U is singular exactly when some M ≠ 0 maps every other point onto its ray,
// M P'_k ∥ x_c,k = R P'_k + T' (then vec(M) is a null vector and R_vec is determined only up to
// multiples of it). Two practical cases, neither curable by another choice of reference:
//   - the points other than P_ref lie on one plane c·P' = 1 (not through P_ref):
//     M = R + T' cᵀ maps each of them exactly onto its ray;
//   - the others lie on a plane n·P' = 0 through P_ref, plus one point q: M = x_c,q nᵀ sends the
//     plane's points to 0 and q onto its ray.
// So "a plane plus one point" is singular for every reference (as for the DLT, where the plane
// gives 8 constraints and the point 2 of 11); it is refused up front (DegenerateError naming the
// lone point) because with pixel noise U is not exactly singular and the estimate would be
// noise. Beyond such configurations (generally: the points and the camera centre on a twisted
// cubic through P_ref), the choice of P_ref matters little (measured over 2000 random 0.3 m
// objects at 1 m, 0.5 px, N = 10 and 20: RMS rotation errors within −15% … +35% of the first
// point's for the farthest-from-centroid and the nearest-to-centroid point), so the first point
// is P_ref, as in the paper. Its ray carries the whole translation direction, so P_ref's pixel
// noise goes straight into T (the paper's "translation cannot be improved"; the refinement removes
// it). U's reciprocal condition number σ_min/σ_max is reported; below 1e-12 (numerically
// singular: another critical configuration) DegenerateError. So is a scale a that is not positive
// and finite (all image points on P_ref's ray: the object has no extent in the image). U scales
// uniformly with the object's unit, so these tests do not depend on it.
//
// Units: object points in any length unit; T comes out in the same unit.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "hecal/geometry/types.h"
#include "hecal/pose/camera_model.h"

namespace hecal::pose {

struct LinearPoseOptions {
  // Coplanarity test of all points and of all points but one: σ3 ≤ planarity_tolerance · σ1
  // (see above). Flatter objects leave U's smallest singular value
  // within the pixel noise; the DLT (dlt_pose.h) treats them as planes at the same tolerance.
  double planarity_tolerance = 1e-3;  // in (0, 1)

  // core/options_check.h: false naming LinearPoseOptions.planarity_tolerance outside (0, 1).
  bool IsValid(std::string* why) const;
};

struct LinearPoseResult {
  Pose T_camera_target = Pose::Identity();
  double reciprocal_condition = 0.0;  // σ_min/σ_max of U
  // ‖R̂ − R‖_F / √3: how far step 3's estimate is from the rotation step 4 chose (0 for exact
  // data; the RMS error of a rotation's entries). Above kUnreliableRotationResidual step 3 was
  // swamped by noise or by wrong correspondences and the pose may be far off.
  double rotation_residual = 0.0;
};

// Measured on 8000 random problems (N = 6…20 points in a 0.4 m cube at 1 m, σ = 0.1…2 px): every
// estimate with rotation_residual < 0.3 was within 24° of the truth — close enough for the
// refinement to converge — while 95 of the 120 above 0.5 were more than 30° off. Two swapped
// correspondences give ≈ 0.8–0.9.
inline constexpr double kUnreliableRotationResidual = 0.3;

// From normalised image coordinates (x_k, y_k) = (x_c/z_c, y_c/z_c) (F = 1).
LinearPoseResult LinearPoseNormalized(const std::vector<Eigen::Vector3d>& object_points,
                                      const std::vector<Eigen::Vector2d>& normalized,
                                      const LinearPoseOptions& options = {});

// From pixels: undistorts them with `camera` (UndistortPoints), then LinearPoseNormalized.
LinearPoseResult LinearPose(const std::vector<Eigen::Vector3d>& object_points,
                            const std::vector<Eigen::Vector2d>& pixels, const CameraModel& camera,
                            const LinearPoseOptions& options = {});

// The shape of a point set: singular values σ1 ≥ σ2 ≥ σ3 of the centred points (object units),
// their centroid, scatter Σ (p − c)(p − c)ᵀ and principal axes (columns, a right-handed rotation;
// the last one is the normal of the least-squares plane). Shared by the linear-pose and DLT
// preconditions.
struct PointSpread {
  Eigen::Vector3d singular_values = Eigen::Vector3d::Zero();
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();

  // σ3 ≤ tolerance · σ1.
  bool Coplanar(double tolerance) const;
  // σ2 ≤ tolerance · σ1.
  bool Collinear(double tolerance) const;
};
PointSpread AnalyseSpread(const std::vector<Eigen::Vector3d>& points);

// A point whose removal leaves the others coplanar (σ3 ≤ tolerance · σ1 of the rest) when the
// whole set is not: "a plane plus one point", which no linear method resolves (see above).
// Removing point j from N points leaves the scatter S − N/(N−1) (p_j − c)(p_j − c)ᵀ, so this is
// O(N). nullopt when there is none (or the whole set is coplanar).
std::optional<std::size_t> LonePointOffAPlane(const std::vector<Eigen::Vector3d>& points,
                                              const PointSpread& spread, double tolerance);

// Throws hecal::InputError (source "image points") when the counts differ or a value is not
// finite. Shared by every pose method.
void CheckCorrespondences(const std::vector<Eigen::Vector3d>& object_points,
                          const std::vector<Eigen::Vector2d>& image_points);

}  // namespace hecal::pose
