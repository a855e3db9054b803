// Pinhole + plumb_bob projection, its Jacobian, and the Gauss–Newton undistortion (see
// camera_model.h for the model).
//
// Jacobian of the distortion map (x, y) → (x_d, y_d), with ρ = radial, ρ' = dρ/d(r²)
// = k1 + 2 k2 r² + 3 k3 r⁴:
//   ∂x_d/∂x = ρ + 2x² ρ' + 2 p1 y + 6 p2 x      ∂x_d/∂y = 2xy ρ' + 2 p1 x + 2 p2 y
//   ∂y_d/∂x = 2xy ρ' + 2 p1 x + 2 p2 y          ∂y_d/∂y = ρ + 2y² ρ' + 6 p1 y + 2 p2 x
// and of the perspective division (x, y) = (X/Z, Y/Z):
//   ∂(x, y)/∂(X, Y, Z) = [ 1/Z  0  −X/Z² ;  0  1/Z  −Y/Z² ].
#include "hecal/pose/camera_model.h"

#include <Eigen/LU>
#include <cmath>
#include <sstream>

#include "hecal/core/error.h"

namespace hecal::pose {
namespace {

// Undistortion: Gauss–Newton iterations, step halvings per iteration, and the acceptance
// tolerance on the reproduced pixel.
constexpr int kMaxIterations = 100;
constexpr int kMaxHalvings = 30;
constexpr double kPixelTolerance = 1e-9;

// The radial factor 1 + k1 r² + k2 r⁴ + k3 r⁶ at r² = r2.
double Radial(const std::array<double, 5>& d, double r2) {
  return 1.0 + r2 * (d[0] + r2 * (d[1] + r2 * d[4]));
}

// The plumb_bob map from normalised to distorted normalised coordinates, and its 2×2 Jacobian
// when `jacobian` is not null.
Eigen::Vector2d Distort(const std::array<double, 5>& d, const Eigen::Vector2d& p,
                        Eigen::Matrix2d* jacobian) {
  const double k1 = d[0], k2 = d[1], p1 = d[2], p2 = d[3], k3 = d[4];
  const double x = p.x(), y = p.y();
  const double r2 = x * x + y * y;
  const double radial = Radial(d, r2);
  const Eigen::Vector2d distorted(x * radial + 2.0 * p1 * x * y + p2 * (r2 + 2.0 * x * x),
                                  y * radial + p1 * (r2 + 2.0 * y * y) + 2.0 * p2 * x * y);
  if (jacobian != nullptr) {
    const double radial_slope = k1 + r2 * (2.0 * k2 + 3.0 * k3 * r2);
    const double cross = 2.0 * x * y * radial_slope + 2.0 * p1 * x + 2.0 * p2 * y;
    *jacobian << radial + 2.0 * x * x * radial_slope + 2.0 * p1 * y + 6.0 * p2 * x, cross, cross,
        radial + 2.0 * y * y * radial_slope + 6.0 * p1 * y + 2.0 * p2 * x;
  }
  return distorted;
}

// A difference of distorted normalised coordinates, measured in pixels.
double PixelMismatch(const CameraModel& camera, const Eigen::Vector2d& distorted_error) {
  return std::hypot(camera.fx * distorted_error.x(), camera.fy * distorted_error.y());
}

}  // namespace

CameraModel CameraModel::Pinhole(double focal) {
  CameraModel camera;
  camera.fx = focal;
  camera.fy = focal;
  return camera;
}

bool CameraModel::HasDistortion() const {
  for (double coefficient : distortion) {
    if (coefficient != 0.0) return true;
  }
  return false;
}

Eigen::Vector2d Project(const CameraModel& camera, const Eigen::Vector3d& point_camera) {
  return Project(camera, point_camera, nullptr);
}

Eigen::Vector2d Project(const CameraModel& camera, const Eigen::Vector3d& point_camera,
                        Eigen::Matrix<double, 2, 3>* jacobian) {
  const double inverse_z = 1.0 / point_camera.z();
  const Eigen::Vector2d normalised = point_camera.head<2>() * inverse_z;
  Eigen::Matrix2d distortion_jacobian;
  const Eigen::Vector2d distorted =
      Distort(camera.distortion, normalised, jacobian != nullptr ? &distortion_jacobian : nullptr);
  if (jacobian != nullptr) {
    Eigen::Matrix<double, 2, 3> division;
    division << inverse_z, 0.0, -normalised.x() * inverse_z, 0.0, inverse_z,
        -normalised.y() * inverse_z;
    *jacobian = Eigen::Vector2d(camera.fx, camera.fy).asDiagonal() * distortion_jacobian * division;
  }
  return {camera.fx * distorted.x() + camera.cx, camera.fy * distorted.y() + camera.cy};
}

IntrinsicParameters IntrinsicsOf(const CameraModel& camera) {
  IntrinsicParameters parameters;
  parameters << camera.fx, camera.fy, camera.cx, camera.cy, camera.distortion[0],
      camera.distortion[1], camera.distortion[2], camera.distortion[3], camera.distortion[4];
  return parameters;
}

CameraModel WithIntrinsics(const CameraModel& camera, const double* parameters) {
  CameraModel out = camera;
  out.fx = parameters[0];
  out.fy = parameters[1];
  out.cx = parameters[2];
  out.cy = parameters[3];
  for (int k = 0; k < 5; ++k) out.distortion[static_cast<size_t>(k)] = parameters[4 + k];
  return out;
}

Eigen::Matrix<double, 2, kNumIntrinsics> ProjectionIntrinsicsJacobian(
    const CameraModel& camera, const Eigen::Vector3d& point_camera) {
  const double x = point_camera.x() / point_camera.z();
  const double y = point_camera.y() / point_camera.z();
  const Eigen::Vector2d distorted = Distort(camera.distortion, {x, y}, nullptr);
  const double r2 = x * x + y * y;
  Eigen::Matrix<double, 2, 5> d_distortion;  // ∂(x_d, y_d) / ∂(k1, k2, p1, p2, k3)
  d_distortion << x * r2, x * r2 * r2, 2.0 * x * y, r2 + 2.0 * x * x, x * r2 * r2 * r2,  //
      y * r2, y * r2 * r2, r2 + 2.0 * y * y, 2.0 * x * y, y * r2 * r2 * r2;
  Eigen::Matrix<double, 2, kNumIntrinsics> J = Eigen::Matrix<double, 2, kNumIntrinsics>::Zero();
  J(0, 0) = distorted.x();
  J(1, 1) = distorted.y();
  J(0, 2) = 1.0;
  J(1, 3) = 1.0;
  J.rightCols<5>() = Eigen::Vector2d(camera.fx, camera.fy).asDiagonal() * d_distortion;
  return J;
}

std::optional<Eigen::Vector2d> Undistort(const CameraModel& camera, const Eigen::Vector2d& pixel) {
  const Eigen::Vector2d target((pixel.x() - camera.cx) / camera.fx,
                               (pixel.y() - camera.cy) / camera.fy);
  if (!target.allFinite()) return std::nullopt;
  if (!camera.HasDistortion()) return target;

  Eigen::Vector2d p = target;
  Eigen::Matrix2d J;
  Eigen::Vector2d error = Distort(camera.distortion, p, &J) - target;
  double mismatch = PixelMismatch(camera, error);
  for (int iteration = 0; iteration < kMaxIterations && mismatch > kPixelTolerance; ++iteration) {
    const double det = J.determinant();
    if (!(std::abs(det) > 0.0)) return std::nullopt;
    // Halve the Gauss–Newton step until it reduces the mismatch (strong distortion far from
    // the centre, where the full step overshoots).
    Eigen::Vector2d step = J.inverse() * error;
    bool improved = false;
    for (int halving = 0; halving < kMaxHalvings && !improved; ++halving) {
      Eigen::Matrix2d J_trial;
      const Eigen::Vector2d trial = p - step;
      const Eigen::Vector2d trial_error = Distort(camera.distortion, trial, &J_trial) - target;
      const double trial_mismatch = PixelMismatch(camera, trial_error);
      improved = trial_mismatch < mismatch;
      if (improved) {
        p = trial;
        J = J_trial;
        error = trial_error;
        mismatch = trial_mismatch;
      }
      step *= 0.5;
    }
    if (!improved) break;
  }
  if (!(mismatch <= kPixelTolerance) || !(J.determinant() > 0.0) ||
      !(Radial(camera.distortion, p.squaredNorm()) > 0.0)) {
    return std::nullopt;
  }
  return p;
}

std::vector<Eigen::Vector2d> UndistortPoints(const CameraModel& camera,
                                             const std::vector<Eigen::Vector2d>& pixels) {
  std::vector<Eigen::Vector2d> normalised;
  normalised.reserve(pixels.size());
  for (const Eigen::Vector2d& pixel : pixels) {
    const std::optional<Eigen::Vector2d> p = Undistort(camera, pixel);
    if (!p) {
      std::ostringstream problem;
      problem << "image point " << normalised.size() + 1 << " at (" << pixel.x() << ", "
              << pixel.y()
              << ") px cannot be undistorted: the distortion model has no physical preimage there";
      throw InputError("image points", 0, problem.str(),
                       "check the intrinsics (distortion coefficients) or remove the point");
    }
    normalised.push_back(*p);
  }
  return normalised;
}

Eigen::Vector3d PixelRay(const CameraModel& camera, const Eigen::Vector2d& pixel,
                         const std::string& source, int line) {
  const std::optional<Eigen::Vector2d> normalised = Undistort(camera, pixel);
  if (!normalised) {
    throw InputError(source, line,
                     "pixel (" + std::to_string(pixel.x()) + ", " + std::to_string(pixel.y()) +
                         ") cannot be undistorted",
                     "check the pixel against the image size and the intrinsics");
  }
  return Eigen::Vector3d(normalised->x(), normalised->y(), 1.0).normalized();
}

}  // namespace hecal::pose
