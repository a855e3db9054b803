// Camera motion from the affinity of a planar contour (docs/contour.md#motion-from-an-affinity; the
// contour paper eqs. 5–16).
//
// Frame and model (object-centred, weak perspective). In the initial view the target plane is
// fronto-parallel at distance Z0 on the optical axis. After the motion a target point p (plane
// z = 0, target frame) is at x_camera = R p + (Tx, Ty, Z0 + Tz); weak perspective projects every
// point with the depth of the target origin, Z0 + Tz, so the image d = f (x, y)/Z0 of the
// initial view becomes d' = M d + t with
//   M = Z0/(Z0 + Tz) [R11 R12; R21 R22],   t = f/(Z0 + Tz) (Tx, Ty)            (eqs. 5–6)
// (the paper's eq. 6 leaves f out; eqs. 14–15 put it back). Image coordinates are measured from
// the principal point in the unit of f; Tx, Ty, Tz are in the unit of Z0.
//
// Inverse (eqs. 9–15): λ1 ≥ λ2 the eigenvalues of M Mᵀ = Rz(φ) diag(L, L cos²θ) Rz(φ)ᵀ,
//   1 + Tz/Z0 = 1/√λ1,  Tx = Z0 tx/(f √λ1),  Ty = Z0 ty/(f √λ1),
//   θ = atan2(√(λ1 − λ2), √λ2)   (= acos √(λ2/λ1), computed without its cancellation near 0),
//   φ = the direction of the λ1 eigenvector = ½ atan2(2 (MMᵀ)12, (MMᵀ)11 − (MMᵀ)22),
//   Rz(ψ) from the first row of (1 + Tz/Z0) diag(1, 1/cos θ) Rz(−φ) M (eq. 12; the first row
//   does not divide by cos θ), and R = Rz(φ) Rx(θ) Rz(ψ) (eq. 7).
// λ2 is det(M)²/λ1 and λ1 − λ2 = √(((MMᵀ)11 − (MMᵀ)22)² + 4 (MMᵀ)12²), both free of
// cancellation, so the inverse is exact to rounding for every θ in [0, π/2).
//
// The Necker ambiguity (docs/contour.md#rotation-representation). Weak perspective sees R and its
// mirror N R N, N = diag(1, 1, −1) (the plane tilted the other way), identically: both have the
// same 2×2 block. Each rotation form returns one of the two, deterministically:
//   zxz (R = Rz(φ) Rx(θ) Rz(ψ)):  θ ∈ [0, π/2), φ ∈ [0, π), ψ ∈ [0, 2π). θ = 0 (λ1 = λ2, the
//       gimbal lock of this form): φ = 0 and ψ is the whole in-plane rotation.
//   zyx (roll–pitch–yaw, R = Rz(c) Ry(b) Rx(a), the paper's eq. 16; euler = (c, b, a), i.e.
//       (Rz, Ry, Rx)): Rz ∈ [0, 2π), |Rx|, |Ry| < π/2, and of the mirror pair the member with
//       Rx + Ry ≥ 0 (at Rx + Ry = 0: Rx ≥ 0). The paper restricts both to [0, π/2); that rule
//       picks the same member whenever Rx and Ry share a sign, and for opposite signs (where no
//       member has both ≥ 0) it keeps the larger one positive, so it is defined everywhere.
// Singular input (DegenerateError): det M ≤ 0 — a singular M (λ2 = 0: the plane seen edge-on,
// θ = π/2, beyond the range) or a reflection (not a rigid motion seen from the front); a
// non-finite S; Z0 + Tz ≤ 0 never arises (√λ1 > 0).
#pragma once

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "hecal/geometry/types.h"

namespace hecal::contour {

enum class RotationForm { kZyx, kZxz };
std::optional<RotationForm> ParseRotationForm(std::string_view name);  // "zyx", "zxz"
std::string_view RotationFormName(RotationForm form);                  // "zyx", "zxz"
std::string_view RotationSequence(RotationForm form);                  // "ZYX", "ZXZ"

// The camera of the model: focal length f (the unit of image coordinates and of tx, ty) and the
// initial distance Z0 (the unit of the translation).
struct ContourCamera {
  double focal = 1.0;
  double z0 = 1.0;

  // core/options_check.h: false naming ContourCamera.focal or .z0 (not finite and positive).
  bool IsValid(std::string* why) const;
};
// RequireValid(camera): throws hecal::InputError (source "ContourCamera.focal" /
// "ContourCamera.z0") unless both are finite and positive.
void ValidateContourCamera(const ContourCamera& camera);

struct ContourPose {
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();  // (Tx, Ty, Tz), Z0's unit
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d euler = Eigen::Vector3d::Zero();  // radians, in RotationSequence(form) order
  RotationForm form = RotationForm::kZyx;
};

// The motion of a shape vector (above). Throws hecal::DegenerateError for singular input.
ContourPose PoseFromShape(const Vector6d& shape, const ContourCamera& camera, RotationForm form);

// The forward weak-perspective model (eqs. 5–6): the shape vector of a motion. Throws
// hecal::DegenerateError when the plane is edge-on or seen from behind (R33 ≤ 0) or behind the
// camera (Z0 + Tz ≤ 0).
Vector6d ShapeFromPose(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& translation,
                       const ContourCamera& camera);

// The Euler angles of R in the form's sequence (RotationSequence), the full-circle ones (Rz; φ, ψ)
// in [0, 2π); no choice of Necker member (CanonicalPose makes it).
Eigen::Vector3d EulerAngles(const Eigen::Matrix3d& rotation, RotationForm form);

// N R N, N = diag(1, 1, −1): the Necker mirror of R.
Eigen::Matrix3d NeckerMirror(const Eigen::Matrix3d& rotation);
// The member of {R, NeckerMirror(R)} that PoseFromShape returns in `form` (R33 > 0), with its
// Euler angles in the form's ranges.
ContourPose CanonicalPose(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& translation,
                          RotationForm form);

// The six pose parameters as one vector, lengths then angles: (Tx, Ty, Tz, Rx, Ry, Rz) for zyx
// and (Tx, Ty, Tz, φ, θ, ψ) for zxz (radians), and their names.
Vector6d PoseParameters(const ContourPose& pose);
std::array<std::string_view, 6> PoseParameterNames(RotationForm form);
// Which parameters are angles with the full-circle range [0, 2π) (Rz; φ and ψ), where statistics
// must unwrap.
std::array<bool, 6> CircularParameters(RotationForm form);

}  // namespace hecal::contour
