// Euler angles in all 12 axis sequences, intrinsic and extrinsic (docs/conventions.md).
//
// A sequence is written as three axis letters: lowercase = extrinsic (fixed axes), uppercase =
// intrinsic (moving axes). Angles (a1, a2, a3) are applied in the written order:
//   extrinsic "xyz": R = Rz(a3) · Ry(a2) · Rx(a1)      (rotate about fixed x, then fixed y, ...)
//   intrinsic "XYZ": R = Rx(a1) · Ry(a2) · Rz(a3)      (rotate about x, then the new y, ...)
// so "xyz" with (a, b, c) equals "ZYX" with (c, b, a). This is scipy.spatial.transform's
// convention (scipy ≥ 1.4, `Rotation.from_euler`), which the tests check against.
// Tait–Bryan sequences (three distinct axes, e.g. xyz, ZYX) and proper Euler sequences (first ==
// third, e.g. ZXZ — the form of the contour paper, docs/contour.md#motion-from-an-affinity: R =
// Rz(φ) Rx(θ) Rz(ψ)).
//
// EulerFromMatrix returns a1, a3 ∈ (−π, π] and a2 ∈ [−π/2, π/2] (Tait–Bryan) or [0, π] (proper).
// Gimbal lock — a2 within kGimbalLockTolerance of ±π/2 (Tait–Bryan) or of 0 / π (proper): only
// a1 ± a3 is observable; hecal then sets a3 = 0 and puts the whole rotation about that axis in
// a1 (the same choice as scipy). Deterministic. Outside that band the angles reproduce R to
// rounding (a3 is extracted after removing a1, so this holds right up to the band, e.g. 1.5e-7
// from the lock); exactly at the lock too. Inside the band, at a distance δ < 1e-7 from the lock,
// forcing a3 = 0 costs a reconstruction error of at most δ·|a3| (< 4e-7): the price of a
// deterministic answer where a1 and a3 are not separately observable.
#pragma once

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace hecal {

inline constexpr double kGimbalLockTolerance = 1e-7;  // radians, on the middle angle

class EulerSequence {
 public:
  // Parses "xyz", "ZYX", "zxz", ...: three letters from x/y/z, all lowercase or all uppercase,
  // no two consecutive axes equal. Returns nullopt on anything else.
  static std::optional<EulerSequence> Parse(std::string_view text);

  // Axis indices 0 = x, 1 = y, 2 = z, in the written order.
  const std::array<int, 3>& axes() const { return axes_; }
  bool intrinsic() const { return intrinsic_; }
  bool proper() const { return axes_[0] == axes_[2]; }  // proper Euler (e.g. ZXZ)
  std::string ToString() const;

  // The same rotation written the other way: extrinsic "xyz" ↔ intrinsic "ZYX" (angles reversed).
  EulerSequence Reversed() const;

  friend bool operator==(const EulerSequence&, const EulerSequence&) = default;

 private:
  EulerSequence(std::array<int, 3> axes, bool intrinsic) : axes_(axes), intrinsic_(intrinsic) {}
  std::array<int, 3> axes_;
  bool intrinsic_;
};

// Elementary rotation about axis 0/1/2 by `angle` radians.
Eigen::Matrix3d ElementaryRotation(int axis, double angle);

Eigen::Matrix3d MatrixFromEuler(const Eigen::Vector3d& angles, const EulerSequence& sequence);
Eigen::Vector3d EulerFromMatrix(const Eigen::Matrix3d& R, const EulerSequence& sequence);

}  // namespace hecal
