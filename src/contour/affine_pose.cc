// Camera motion from the affinity of a planar contour: see affine_pose.h.
#include "hecal/contour/affine_pose.h"

#include <cmath>
#include <numbers>
#include <string>

#include "hecal/contour/shape_space.h"
#include "hecal/core/error.h"
#include "hecal/core/number_text.h"
#include "hecal/core/options_check.h"
#include "hecal/geometry/euler.h"

namespace hecal::contour {
namespace {

constexpr double kPi = std::numbers::pi;

// a wrapped into [0, period).
double WrapTo(double a, double period) {
  double w = std::fmod(a, period);
  if (w < 0.0) w += period;
  if (w >= period) w = 0.0;  // −tiny + period rounding to period
  return w;
}

// Whether the zyx form keeps R itself (rather than its mirror): Rx + Ry ≥ 0, ties Rx ≥ 0.
bool ZyxKeeps(const Eigen::Vector3d& e) {
  const double sum = e(2) + e(1);
  return sum > 0.0 || (sum == 0.0 && e(2) >= 0.0);
}

ContourPose Finish(const Eigen::Matrix3d& R_zxz, const Eigen::Vector3d& zxz_angles,
                   const Eigen::Vector3d& translation, RotationForm form) {
  ContourPose pose;
  pose.translation = translation;
  pose.form = form;
  if (form == RotationForm::kZxz) {
    pose.rotation = R_zxz;
    pose.euler = zxz_angles;
    return pose;
  }
  pose.rotation = R_zxz;
  pose.euler = EulerAngles(R_zxz, RotationForm::kZyx);
  if (!ZyxKeeps(pose.euler)) {
    pose.rotation = NeckerMirror(R_zxz);
    pose.euler = EulerAngles(pose.rotation, RotationForm::kZyx);
  }
  return pose;
}

}  // namespace

std::optional<RotationForm> ParseRotationForm(std::string_view name) {
  if (name == "zyx") return RotationForm::kZyx;
  if (name == "zxz") return RotationForm::kZxz;
  return std::nullopt;
}

std::string_view RotationFormName(RotationForm form) {
  return form == RotationForm::kZyx ? "zyx" : "zxz";
}

std::string_view RotationSequence(RotationForm form) {
  return form == RotationForm::kZyx ? "ZYX" : "ZXZ";
}

Eigen::Vector3d EulerAngles(const Eigen::Matrix3d& rotation, RotationForm form) {
  Eigen::Vector3d e = EulerFromMatrix(rotation, *EulerSequence::Parse(RotationSequence(form)));
  e(0) = WrapTo(e(0), 2.0 * kPi);
  if (form == RotationForm::kZxz) e(2) = WrapTo(e(2), 2.0 * kPi);
  return e;
}

bool ContourCamera::IsValid(std::string* why) const {
  if (!std::isfinite(focal) || !(focal > 0.0)) {
    return Invalid(why, "ContourCamera.focal", "the focal length must be a positive number",
                   "give f in the unit of the image coordinates (e.g. 50 for mm)");
  }
  if (!std::isfinite(z0) || !(z0 > 0.0)) {
    return Invalid(why, "ContourCamera.z0", "the initial distance Z0 must be a positive number",
                   "give the distance from the camera to the target in the first view");
  }
  return true;
}

void ValidateContourCamera(const ContourCamera& camera) {
  RequireValid(camera);
}

ContourPose PoseFromShape(const Vector6d& shape, const ContourCamera& camera, RotationForm form) {
  if (!shape.allFinite()) {
    throw DegenerateError("the camera motion: the shape vector is not finite",
                          "give six finite numbers (tx, ty, M11 − 1, M22 − 1, M21, M12)");
  }
  const Eigen::Matrix2d M = AffinityMatrix(shape);
  const double det = M.determinant();
  if (!(det > 0.0)) {
    throw DegenerateError(
        det == 0.0
            ? "the camera motion: the affinity M is singular (det M = 0), so M Mᵀ is not "
              "positive definite: the plane is seen edge-on, a tilt of 90°, beyond the "
              "range [0°, 90°)"
            : "the camera motion: the affinity reverses orientation (det M = " + NumberText(det) +
                  " < 0), which no rigid motion of a plane seen from the front gives",
        "check the shape vector's order (tx, ty, M11 − 1, M22 − 1, M21, M12) and signs");
  }
  const Eigen::Matrix2d A = M * M.transpose();
  const double half_sum = 0.5 * (A(0, 0) + A(1, 1));
  const double half_gap = 0.5 * std::hypot(A(0, 0) - A(1, 1), 2.0 * A(0, 1));  // (λ1 − λ2)/2
  const double lambda1 = half_sum + half_gap;
  const double lambda2 = det * det / lambda1;
  const double scale = std::sqrt(lambda1);  // Z0/(Z0 + Tz)

  Eigen::Vector3d translation;
  translation.x() = camera.z0 * shape(0) / (camera.focal * scale);
  translation.y() = camera.z0 * shape(1) / (camera.focal * scale);
  translation.z() = camera.z0 * (1.0 / scale - 1.0);

  const double theta = std::atan2(std::sqrt(2.0 * half_gap), std::sqrt(lambda2));
  // φ: the λ1 eigenvector's direction, ½ atan2(2 A12, A11 − A22) ∈ (−π/2, π/2], into [0, π).
  double phi = 0.5 * std::atan2(2.0 * A(0, 1), A(0, 0) - A(1, 1));
  if (phi < 0.0) phi += kPi;
  if (phi >= kPi) phi = 0.0;
  // First row of (1/scale) Rz(−φ) M = (cos ψ, −sin ψ) (eq. 12 without the 1/cos θ row).
  const Eigen::Matrix2d Rphi_t =
      (Eigen::Matrix2d() << std::cos(phi), std::sin(phi), -std::sin(phi), std::cos(phi)).finished();
  const Eigen::RowVector2d first = (Rphi_t * M).row(0) / scale;
  const double psi = WrapTo(std::atan2(-first(1), first(0)), 2.0 * kPi);
  const Eigen::Vector3d angles(phi, theta, psi);
  const Eigen::Matrix3d R = MatrixFromEuler(angles, *EulerSequence::Parse("ZXZ"));
  ContourPose pose = Finish(R, angles, translation, form);
  // Entries so large that M Mᵀ overflows (|M| ≳ 1e154) give inf/NaN above: never a pose.
  if (!pose.translation.allFinite() || !pose.rotation.allFinite() || !pose.euler.allFinite()) {
    throw DegenerateError(
        "the camera motion: the shape vector's entries are too large to give a finite pose "
        "(M Mᵀ overflows; a real view has |M − I| and |tx|, |ty| / f of order 1)",
        "give the shape vector of a tracked contour (tx, ty, M11 − 1, M22 − 1, M21, M12)");
  }
  return pose;
}

Vector6d ShapeFromPose(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& translation,
                       const ContourCamera& camera) {
  if (!(rotation(2, 2) > 0.0)) {
    throw DegenerateError("the contour: the target plane is edge-on or seen from behind (R33 = " +
                              NumberText(rotation(2, 2)) + "), a tilt of 90° or more",
                          "keep the out-of-plane rotation below 90°");
  }
  const double depth = camera.z0 + translation.z();
  if (!(depth > 0.0)) {
    throw DegenerateError(
        "the contour: the target is behind the camera (Z0 + Tz = " + NumberText(depth) + ")",
        "keep Tz > −Z0");
  }
  const Eigen::Matrix2d M = camera.z0 / depth * rotation.topLeftCorner<2, 2>();
  const Eigen::Vector2d t = camera.focal / depth * translation.head<2>();
  return ShapeFromAffinity(M, t);
}

Eigen::Matrix3d NeckerMirror(const Eigen::Matrix3d& rotation) {
  const Eigen::Vector3d n(1.0, 1.0, -1.0);
  return n.asDiagonal() * rotation * n.asDiagonal();
}

ContourPose CanonicalPose(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& translation,
                          RotationForm form) {
  if (!(rotation(2, 2) > 0.0)) {
    throw DegenerateError("the contour: the target plane is edge-on or seen from behind (R33 = " +
                              NumberText(rotation(2, 2)) + ")",
                          "keep the out-of-plane rotation below 90°");
  }
  // The ZXZ angles of R, with θ ∈ (0, π/2) and φ ∈ [0, π) choosing the mirror member.
  const double theta = std::acos(std::min(1.0, rotation(2, 2)));
  const double s = std::sin(theta);
  Eigen::Matrix3d R_zxz = rotation;
  double phi = 0.0, psi = 0.0;
  if (s * s < 1e-24) {  // θ = 0: φ = 0, ψ = the whole in-plane angle
    psi = WrapTo(std::atan2(rotation(1, 0), rotation(0, 0)), 2.0 * kPi);
  } else {
    // R = Rz(φ) Rx(θ) Rz(ψ): R13 = sφ sθ, R23 = −cφ sθ, R31 = sθ sψ, R32 = sθ cψ.
    phi = std::atan2(rotation(0, 2), -rotation(1, 2));
    if (phi < 0.0 || phi >= kPi) {
      R_zxz = NeckerMirror(rotation);
      phi = std::atan2(R_zxz(0, 2), -R_zxz(1, 2));
    }
    phi = WrapTo(phi, kPi);
    psi = WrapTo(std::atan2(R_zxz(2, 0), R_zxz(2, 1)), 2.0 * kPi);
  }
  return Finish(R_zxz, Eigen::Vector3d(phi, theta, psi), translation, form);
}

Vector6d PoseParameters(const ContourPose& pose) {
  Vector6d p;
  p.head<3>() = pose.translation;
  if (pose.form == RotationForm::kZyx) {
    p.tail<3>() << pose.euler(2), pose.euler(1), pose.euler(0);  // (Rx, Ry, Rz)
  } else {
    p.tail<3>() = pose.euler;  // (φ, θ, ψ)
  }
  return p;
}

std::array<std::string_view, 6> PoseParameterNames(RotationForm form) {
  if (form == RotationForm::kZyx) return {"Tx", "Ty", "Tz", "Rx", "Ry", "Rz"};
  return {"Tx", "Ty", "Tz", "phi", "theta", "psi"};
}

std::array<bool, 6> CircularParameters(RotationForm form) {
  if (form == RotationForm::kZyx) return {false, false, false, false, false, true};
  return {false, false, false, true, false, true};
}

}  // namespace hecal::contour
