// Euler angles in all 12 axis sequences, intrinsic and extrinsic (see euler.h).
//
// Both modes are decomposed in the "written product" form R = E_p(c1) · E_q(c2) · E_r(c3):
//   intrinsic "PQR" (a1, a2, a3):  R = E_p(a1) E_q(a2) E_r(a3)   → (c1, c2, c3) = (a1, a2, a3)
//   extrinsic "pqr" (a1, a2, a3):  R = E_r(a3) E_q(a2) E_p(a1)   → axes (r, q, p),
//                                                                   (c1, c2, c3) = (a3, a2, a1)
// With o the axis different from p and q and s = ε_pqo (+1 for a cyclic x→y→z order, −1
// otherwise), the formulas below follow from E_a(θ) e_b = cos θ e_b + sin θ (e_a × e_b):
//   Tait–Bryan (r = o):  R(p,r) = s sin c2,  R(q,r) = −s sin c1 cos c2,  R(r,r) = cos c1 cos c2,
//                        R(p,q) = −s cos c2 sin c3,  R(p,p) = cos c2 cos c3.
//   proper (r = p):      R(p,p) = cos c2,  R(q,p) = sin c1 sin c2,  R(o,p) = −s cos c1 sin c2,
//                        R(p,q) = sin c2 sin c3,  R(p,o) = s sin c2 cos c3.
// The middle angle comes from atan2 of a sine and a cosine, the cosine (Tait–Bryan) or sine
// (proper) taken as a hypot of two entries: accurate everywhere, including at the gimbal lock,
// where an arcsin/arccos would lose half the digits (scipy 1.10 uses arccos and is ~1e-8 off).
//
// Outside gimbal lock one outer angle is read from R and the other from the residual after
// removing it (as in M. Day, "Extracting Euler angles from a rotation matrix", Insomniac Games):
// an error ε in the first angle then reappears in the second, and since
// E_p(ε) E_q(c2) = E_q(c2) E_r(±ε) + O(ε·δ) near a lock at distance δ, the reconstruction stays
// exact to rounding even where ε ≈ 1e-16/δ is large.
// The angle read first is a1 (the first written angle) in both modes, so a3 absorbs the error.
//
// Gimbal lock (|c2 ∓ π/2| < kGimbalLockTolerance for Tait–Bryan, c2 < tol or c2 > π − tol for
// proper): only a1 ± a3 is observable; a3 = 0 and a1 carries the whole rotation about that axis
// (scipy's choice, for intrinsic and extrinsic alike). For an exact lock the result reproduces
// R to rounding; inside the tolerance band but off the lock by δ the residual is δ·|a3_true| at
// most (≤ π·1e-7 per entry; measured), the price of the a3 = 0 convention: no (a1, a2, 0) does
// better, since such rotations lie off the a3 = 0 family by that much.
#include "hecal/geometry/euler.h"

#include <cassert>
#include <cmath>
#include <numbers>

namespace hecal {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kHalfPi = 0.5 * std::numbers::pi;

// Maps an atan2 result from [−π, π] to (−π, π]: atan2 returns −π for (−0, x < 0).
double WrapAngle(double angle) {
  if (angle <= -kPi) return angle + 2.0 * kPi;
  if (angle > kPi) return angle - 2.0 * kPi;
  return angle;
}

// Levi-Civita symbol ε_abc for distinct a, b and c the remaining axis: +1 for cyclic x→y→z.
int Parity(int a, int b) {
  return (b - a + 3) % 3 == 1 ? 1 : -1;
}

// The geometry of one written product R = E_p(c1) E_q(c2) E_r(c3).
struct Axes {
  int p, q, r;
  int o;  // the axis different from p and q (equal to r for Tait–Bryan)
  double s;
  bool proper;
};

Axes MakeAxes(int p, int q, int r) {
  Axes axes{p, q, r, 3 - p - q, static_cast<double>(Parity(p, q)), p == r};
  return axes;
}

// A = E_p(x) E_q(y): column q is E_p(x) e_q = cos x e_q + s sin x e_o.
double FirstAngleFromColumnQ(const Eigen::Matrix3d& A, const Axes& ax) {
  return std::atan2(ax.s * A(ax.o, ax.q), A(ax.q, ax.q));
}

// A = E_q(y) E_r(z): row q is (E_r(−z) e_q)ᵀ = cos z e_q − sin z (e_r × e_q).
//   Tait–Bryan (r = o): e_o × e_q = −s e_p;  proper (r = p): e_p × e_q = s e_o.
double LastAngleFromRowQ(const Eigen::Matrix3d& A, const Axes& ax) {
  if (ax.proper) return std::atan2(-ax.s * A(ax.q, ax.o), A(ax.q, ax.q));
  return std::atan2(ax.s * A(ax.q, ax.p), A(ax.q, ax.q));
}

// Decomposes R = E_p(c1) E_q(c2) E_r(c3). At gimbal lock the angle named by `zero_first` is set
// to zero (c1 when true, c3 otherwise) and the other carries the rotation. Outside the lock the
// angle that is zeroed at the lock is extracted from the residual.
Eigen::Vector3d Decompose(const Eigen::Matrix3d& R, const Axes& ax, bool zero_first) {
  double c1, c2, c3;
  bool lock;
  if (ax.proper) {
    c2 = std::atan2(std::hypot(R(ax.q, ax.p), R(ax.o, ax.p)), R(ax.p, ax.p));  // [0, π]
    lock = c2 < kGimbalLockTolerance || c2 > kPi - kGimbalLockTolerance;
  } else {
    c2 = std::atan2(ax.s * R(ax.p, ax.r), std::hypot(R(ax.q, ax.r), R(ax.r, ax.r)));  // ±π/2
    lock = std::abs(c2) > kHalfPi - kGimbalLockTolerance;
  }

  if (lock) {
    if (zero_first) {
      c1 = 0.0;
      c3 = LastAngleFromRowQ(R, ax);
    } else {
      c3 = 0.0;
      c1 = FirstAngleFromColumnQ(R, ax);
    }
  } else if (!zero_first) {
    // c1 from column r of R, then c3 from M = E_p(−c1) R = E_q(c2) E_r(c3).
    c1 = ax.proper ? std::atan2(R(ax.q, ax.p), -ax.s * R(ax.o, ax.p))
                   : std::atan2(-ax.s * R(ax.q, ax.r), R(ax.r, ax.r));
    const Eigen::Matrix3d M = ElementaryRotation(ax.p, -c1) * R;
    c3 = LastAngleFromRowQ(M, ax);
  } else {
    // c3 from row p of R, then c1 from N = R E_r(−c3) = E_p(c1) E_q(c2).
    c3 = ax.proper ? std::atan2(R(ax.p, ax.q), ax.s * R(ax.p, ax.o))
                   : std::atan2(-ax.s * R(ax.p, ax.q), R(ax.p, ax.p));
    const Eigen::Matrix3d N = R * ElementaryRotation(ax.r, -c3);
    c1 = FirstAngleFromColumnQ(N, ax);
  }
  // "+ 0.0" turns a −0 (from atan2 of −0) into +0, so files never show "-0".
  return Eigen::Vector3d(WrapAngle(c1) + 0.0, c2 + 0.0, WrapAngle(c3) + 0.0);
}

int AxisFromLetter(char letter) {
  switch (letter) {
    case 'x':
    case 'X':
      return 0;
    case 'y':
    case 'Y':
      return 1;
    case 'z':
    case 'Z':
      return 2;
    default:
      return -1;
  }
}

}  // namespace

std::optional<EulerSequence> EulerSequence::Parse(std::string_view text) {
  if (text.size() != 3) return std::nullopt;
  std::array<int, 3> axes{};
  int upper = 0;
  for (int i = 0; i < 3; ++i) {
    const char c = text[static_cast<size_t>(i)];
    axes[static_cast<size_t>(i)] = AxisFromLetter(c);
    if (axes[static_cast<size_t>(i)] < 0) return std::nullopt;
    if (c >= 'X' && c <= 'Z') ++upper;
  }
  if (upper != 0 && upper != 3) return std::nullopt;  // mixed case
  if (axes[0] == axes[1] || axes[1] == axes[2]) return std::nullopt;
  return EulerSequence(axes, upper == 3);
}

std::string EulerSequence::ToString() const {
  std::string text(3, ' ');
  for (size_t i = 0; i < 3; ++i) {
    text[i] = static_cast<char>((intrinsic_ ? 'X' : 'x') + axes_[i]);
  }
  return text;
}

EulerSequence EulerSequence::Reversed() const {
  return EulerSequence({axes_[2], axes_[1], axes_[0]}, !intrinsic_);
}

Eigen::Matrix3d ElementaryRotation(int axis, double angle) {
  assert(axis >= 0 && axis <= 2);
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  Eigen::Matrix3d E;
  switch (axis) {
    case 0:
      E << 1.0, 0.0, 0.0,  //
          0.0, c, -s,      //
          0.0, s, c;
      break;
    case 1:
      E << c, 0.0, s,     //
          0.0, 1.0, 0.0,  //
          -s, 0.0, c;
      break;
    default:
      E << c, -s, 0.0,  //
          s, c, 0.0,    //
          0.0, 0.0, 1.0;
      break;
  }
  return E;
}

Eigen::Matrix3d MatrixFromEuler(const Eigen::Vector3d& angles, const EulerSequence& sequence) {
  const std::array<int, 3>& axes = sequence.axes();
  const Eigen::Matrix3d E1 = ElementaryRotation(axes[0], angles(0));
  const Eigen::Matrix3d E2 = ElementaryRotation(axes[1], angles(1));
  const Eigen::Matrix3d E3 = ElementaryRotation(axes[2], angles(2));
  // Intrinsic: about the moving axes, so later rotations multiply on the right.
  return sequence.intrinsic() ? Eigen::Matrix3d(E1 * E2 * E3) : Eigen::Matrix3d(E3 * E2 * E1);
}

Eigen::Vector3d EulerFromMatrix(const Eigen::Matrix3d& R, const EulerSequence& sequence) {
  const std::array<int, 3>& axes = sequence.axes();
  if (sequence.intrinsic()) {
    // R = E_a0(a1) E_a1(a2) E_a2(a3); at the lock a3 (= c3) is zero.
    return Decompose(R, MakeAxes(axes[0], axes[1], axes[2]), /*zero_first=*/false);
  }
  // R = E_a2(a3) E_a1(a2) E_a0(a1); at the lock a3 (= c1) is zero.
  const Eigen::Vector3d c = Decompose(R, MakeAxes(axes[2], axes[1], axes[0]), true);
  return Eigen::Vector3d(c(2), c(1), c(0));
}

}  // namespace hecal
