// The pinhole camera with OpenCV's plumb_bob distortion (Brown–Conrady: k1, k2, p1, p2, k3),
// docs/targets.md. Pixel coordinates (u, v) with the origin at the centre of the top-left pixel,
// as OpenCV. A point x_c in the camera frame (z forward, x right, y down) projects to
//   (x, y) = (x_c / z_c, y_c / z_c),  r² = x² + y²,
//   radial = 1 + k1 r² + k2 r⁴ + k3 r⁶,
//   x_d = x·radial + 2 p1 x y + p2 (r² + 2x²),   y_d = y·radial + p1 (r² + 2y²) + 2 p2 x y,
//   u = fx x_d + cx,   v = fy y_d + cy.
// This is exactly cv::projectPoints with rvec = tvec = 0 (tested against it).
// Units: pixels for fx, fy, cx, cy; the distortion coefficients are dimensionless; the point in
// any length unit (only ratios enter).
//
// Undistort inverts the pixel map up to depth: it solves distort(x, y) = ((u − cx)/fx,
// (v − cy)/fy) for the normalised image coordinates (x, y) by Gauss–Newton on the 2×2 system,
// started at the distorted coordinates, halving a step that does not reduce the mismatch. A
// solution is accepted when it reproduces the pixel to 1e-9 px, the distortion map is
// orientation-preserving there (det ∂(x_d, y_d)/∂(x, y) > 0) and the radial factor is positive
// (the ray is not sent across the principal point): beyond the radius where strong barrel
// distortion folds back, a pixel has no physical preimage (or only one on a folded branch: once
// folded, where the determinant is negative, or twice, farther out, where the radial factor is
// negative and the determinant positive again) and Undistort returns nullopt.
#pragma once

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace hecal::pose {

struct CameraModel {
  double fx = 0.0;
  double fy = 0.0;
  double cx = 0.0;
  double cy = 0.0;
  int width = 0;                                                 // pixels; 0 when unknown
  int height = 0;                                                // pixels; 0 when unknown
  std::array<double, 5> distortion = {0.0, 0.0, 0.0, 0.0, 0.0};  // k1, k2, p1, p2, k3

  // A camera with focal length f (pixels), principal point at the origin, no distortion — the
  // linear-pose model X = F x/z, Y = F y/z.
  static CameraModel Pinhole(double focal);
  bool HasDistortion() const;
};

// Projects a point in the camera frame to pixels. Precondition: z > 0 (for z ≤ 0 the value is
// the formula's, which has no physical meaning; callers that may meet such points check z).
Eigen::Vector2d Project(const CameraModel& camera, const Eigen::Vector3d& point_camera);

// Projection and its Jacobian d(u, v) / d(point_camera) (2×3); `jacobian` may be nullptr.
Eigen::Vector2d Project(const CameraModel& camera, const Eigen::Vector3d& point_camera,
                        Eigen::Matrix<double, 2, 3>* jacobian);

// The intrinsic parameters as one vector, in the order (fx, fy, cx, cy, k1, k2, p1, p2, k3) —
// the unknowns of a refinement of the intrinsics (estimation/reprojection_refinement.h).
constexpr int kNumIntrinsics = 9;
using IntrinsicParameters = Eigen::Matrix<double, kNumIntrinsics, 1>;
IntrinsicParameters IntrinsicsOf(const CameraModel& camera);
// `camera` (its width and height) with the intrinsics `parameters` (kNumIntrinsics values).
CameraModel WithIntrinsics(const CameraModel& camera, const double* parameters);

// d(u, v) / d(IntrinsicsOf(camera)) (2×9) at a point in the camera frame (z > 0): with (x, y)
// the normalised and (x_d, y_d) the distorted coordinates, u = fx·x_d + cx, v = fy·y_d + cy and
//   ∂x_d/∂(k1, k2, k3) = x·(r², r⁴, r⁶),  ∂x_d/∂p1 = 2xy,        ∂x_d/∂p2 = r² + 2x²,
//   ∂y_d/∂(k1, k2, k3) = y·(r², r⁴, r⁶),  ∂y_d/∂p1 = r² + 2y²,   ∂y_d/∂p2 = 2xy.
Eigen::Matrix<double, 2, kNumIntrinsics> ProjectionIntrinsicsJacobian(
    const CameraModel& camera, const Eigen::Vector3d& point_camera);

// Normalised, undistorted image coordinates (x, y) of a pixel — the inverse of Project up to
// depth (see above); nullopt when it does not converge or lands on the folded branch (far
// outside the image for strong distortion). Without distortion it is exact and never nullopt.
std::optional<Eigen::Vector2d> Undistort(const CameraModel& camera, const Eigen::Vector2d& pixel);

// Undistort for every pixel, in order. Throws hecal::InputError (source "image points") naming
// the first pixel (1-based position and value) that cannot be undistorted.
std::vector<Eigen::Vector2d> UndistortPoints(const CameraModel& camera,
                                             const std::vector<Eigen::Vector2d>& pixels);

// The unit ray (x, y, 1)/|(x, y, 1)| through a pixel, (x, y) = Undistort(pixel). Throws
// hecal::InputError(source, line) naming the pixel when it cannot be undistorted.
Eigen::Vector3d PixelRay(const CameraModel& camera, const Eigen::Vector2d& pixel,
                         const std::string& source, int line);

}  // namespace hecal::pose
