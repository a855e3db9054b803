// Unit dual quaternions for rigid motions (Daniilidis 1999, §3). See dual_quaternion.h.
//
// Exp / Log in closed form. Write a pure dual quaternion as a + εb (a, b pure quaternions, i.e.
// 3-vectors) and h = |a| (half the rotation angle). In screw terms a + εb = ½ θ̌ ľ, so Exp is
// (cos(θ̌/2), sin(θ̌/2) ľ); expanding the dual sine and cosine and eliminating l, m and d gives
//   Exp(a + εb) = (cos h, σ a) + ε (−σ (a·b), σ b + κ (a·b) a),
//   σ(h) = sin h / h,   κ(h) = (cos h − σ(h)) / h²,
// both smooth at h = 0 (series there), and Log inverts it with a = u/σ, a·b = −w'/σ,
// b = (u' − κ (a·b) a)/σ for the unit q̌ = (w, u) + ε (w', u') with w ≥ 0, h = atan2(|u|, w).
// σ ≥ 2/π on h ∈ [0, π/2], so no step divides by a small number.
#include "hecal/geometry/dual_quaternion.h"

#include <cmath>

#include "hecal/geometry/rotation.h"

namespace hecal {
namespace {

Eigen::Quaterniond FromCoeffs(const Eigen::Vector4d& xyzw) {
  Eigen::Quaterniond q;
  q.coeffs() = xyzw;
  return q;
}

Eigen::Quaterniond Add(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  return FromCoeffs(a.coeffs() + b.coeffs());
}

Eigen::Quaterniond Scale(const Eigen::Quaterniond& q, double s) {
  return FromCoeffs(s * q.coeffs());
}

Eigen::Quaterniond Pure(const Eigen::Vector3d& v) {
  return Eigen::Quaterniond(0.0, v.x(), v.y(), v.z());
}

// σ(h) = sin h / h; series below 1e-4 (first omitted term h⁶/5040 < 1e-27).
double Sinc(double h) {
  if (h < 1e-4) return 1.0 - h * h / 6.0 + h * h * h * h / 120.0;
  return std::sin(h) / h;
}

// κ(h) = (cos h − sin h / h) / h²; series below 1e-2 (first omitted term h⁸/3991680 < 1e-22).
// Above it the closed form's cancellation costs ~1e-16/h² relative, but κ multiplies (a·b) a,
// which is O(h²), so the absolute error stays at rounding level.
double Kappa(double h) {
  const double h2 = h * h;
  if (h < 1e-2) return -1.0 / 3.0 + h2 / 30.0 - h2 * h2 / 840.0 + h2 * h2 * h2 / 45360.0;
  return (std::cos(h) - std::sin(h) / h) / h2;
}

}  // namespace

DualQuaternion::DualQuaternion()
    : real_(Eigen::Quaterniond::Identity()), dual_(0.0, 0.0, 0.0, 0.0) {}

DualQuaternion::DualQuaternion(const Eigen::Quaterniond& real, const Eigen::Quaterniond& dual)
    : real_(real), dual_(dual) {}

DualQuaternion::DualQuaternion(const Eigen::Quaterniond& rotation,
                               const Eigen::Vector3d& translation)
    : real_(rotation.normalized()), dual_(Scale(Pure(translation) * real_, 0.5)) {}

DualQuaternion DualQuaternion::Identity() {
  return DualQuaternion();
}

DualQuaternion DualQuaternion::Zero() {
  return DualQuaternion(Eigen::Quaterniond(0.0, 0.0, 0.0, 0.0),
                        Eigen::Quaterniond(0.0, 0.0, 0.0, 0.0));
}

DualQuaternion DualQuaternion::FromPose(const Pose& T) {
  // QuaternionFromMatrix is canonical, so the result is too (its real part is non-zero).
  return DualQuaternion(QuaternionFromMatrix(T.linear()), Eigen::Vector3d(T.translation()));
}

DualQuaternion DualQuaternion::FromScrew(const Screw& screw) {
  const Eigen::Vector3d l = screw.l.normalized();
  const Eigen::Vector3d m = screw.m - l.dot(screw.m) * l;
  const double c = std::cos(0.5 * screw.theta);
  const double s = std::sin(0.5 * screw.theta);
  const double half_d = 0.5 * screw.d;
  // cos(θ̌/2) = c − ε ½d s,  sin(θ̌/2) ľ = s l + ε (s m + ½d c l).
  const Eigen::Vector3d dual_vec = s * m + half_d * c * l;
  return DualQuaternion(Eigen::Quaterniond(c, s * l.x(), s * l.y(), s * l.z()),
                        Eigen::Quaterniond(-half_d * s, dual_vec.x(), dual_vec.y(), dual_vec.z()));
}

DualQuaternion DualQuaternion::Conjugate() const {
  return DualQuaternion(real_.conjugate(), dual_.conjugate());
}

DualQuaternion DualQuaternion::Inverse() const {
  const Eigen::Quaterniond real_inv = real_.inverse();
  return DualQuaternion(real_inv, Scale(real_inv * dual_ * real_inv, -1.0));
}

DualNumber DualQuaternion::Norm() const {
  const double n = real_.norm();
  return DualNumber{n, real_.coeffs().dot(dual_.coeffs()) / n};
}

void DualQuaternion::Normalize() {
  // (q + εq') / (a + εb) = q/a + ε (q'/a − q b/a²), with a = |q|, b = q·q'/|q|.
  const DualNumber n = Norm();
  const Eigen::Vector4d real = real_.coeffs() / n.real;
  const Eigen::Vector4d dual = dual_.coeffs() / n.real - real * (n.dual / n.real);
  real_.coeffs() = real;
  dual_.coeffs() = dual;
}

DualQuaternion DualQuaternion::Normalized() const {
  DualQuaternion result = *this;
  result.Normalize();
  return result;
}

DualQuaternion DualQuaternion::Canonical() const {
  const Eigen::Matrix<double, 8, 1> v = ToVector();
  for (int i = 0; i < 8; ++i) {
    if (v(i) > 0.0) return *this;
    if (v(i) < 0.0) return *this * -1.0;
  }
  return *this;
}

DualQuaternion DualQuaternion::Exp() const {
  const Eigen::Vector3d a = real_.vec();
  const Eigen::Vector3d b = dual_.vec();
  const double h = a.norm();
  const double sigma = Sinc(h);
  const double ab = a.dot(b);
  const Eigen::Vector3d dual_vec = sigma * b + (Kappa(h) * ab) * a;
  const DualQuaternion pure_exp(
      Eigen::Quaterniond(std::cos(h), sigma * a.x(), sigma * a.y(), sigma * a.z()),
      Eigen::Quaterniond(-sigma * ab, dual_vec.x(), dual_vec.y(), dual_vec.z()));
  // Scalar part s + εs' commutes with everything: exp(s + εs') = eˢ (1 + εs').
  const double scale = std::exp(real_.w());
  return DualQuaternion(Scale(pure_exp.real_, scale),
                        Scale(Add(pure_exp.dual_, Scale(pure_exp.real_, dual_.w())), scale));
}

DualQuaternion DualQuaternion::Log() const {
  const DualNumber norm = Norm();
  DualQuaternion unit = Normalized();
  // q̌ and −q̌ are the same pose; take the one with rotation angle ≤ π (w ≥ 0). At exactly π
  // (w = 0) use so3::Log's rule, the largest-magnitude component of ω positive, so that this
  // agrees with ½ se3::Log(ToPose()) there too.
  const Eigen::Vector3d u0 = unit.real_.vec();
  bool flip = unit.real_.w() < 0.0;
  if (unit.real_.w() == 0.0) {
    Eigen::Index i;
    u0.cwiseAbs().maxCoeff(&i);
    flip = u0(i) < 0.0;
  }
  if (flip) unit = unit * -1.0;
  const Eigen::Vector3d u = unit.real_.vec();
  const double h = std::atan2(u.norm(), unit.real_.w());
  const double sigma = Sinc(h);
  const Eigen::Vector3d a = u / sigma;
  const double ab = -unit.dual_.w() / sigma;
  const Eigen::Vector3d b = (unit.dual_.vec() - (Kappa(h) * ab) * a) / sigma;
  return DualQuaternion(Eigen::Quaterniond(std::log(norm.real), a.x(), a.y(), a.z()),
                        Eigen::Quaterniond(norm.dual / norm.real, b.x(), b.y(), b.z()));
}

Eigen::Vector3d DualQuaternion::TransformPoint(const Eigen::Vector3d& p) const {
  return Rotation() * p + Translation();
}

Eigen::Vector3d DualQuaternion::TransformVector(const Eigen::Vector3d& v) const {
  return Rotation() * v;
}

Eigen::Quaterniond DualQuaternion::Rotation() const {
  return real_.normalized();
}

Eigen::Vector3d DualQuaternion::Translation() const {
  return 2.0 * (dual_ * real_.inverse()).vec();
}

Eigen::Quaterniond DualQuaternion::TranslationQuaternion() const {
  return Pure(Translation());
}

Eigen::Matrix4d DualQuaternion::ToMatrix() const {
  return ToPose().matrix();
}

Pose DualQuaternion::ToPose() const {
  return MakePose(MatrixFromQuaternion(real_), Translation());
}

Screw DualQuaternion::ToScrew() const {
  return ScrewFromPose(ToPose());
}

DualQuaternion DualQuaternion::operator*(const DualQuaternion& other) const {
  // (q + εq')(r + εr') = qr + ε (qr' + q'r), since ε² = 0.
  return DualQuaternion(real_ * other.real_, Add(real_ * other.dual_, dual_ * other.real_));
}

DualQuaternion DualQuaternion::operator+(const DualQuaternion& other) const {
  return DualQuaternion(Add(real_, other.real_), Add(dual_, other.dual_));
}

DualQuaternion DualQuaternion::operator-(const DualQuaternion& other) const {
  return *this + other * -1.0;
}

DualQuaternion DualQuaternion::operator*(double scale) const {
  return DualQuaternion(Scale(real_, scale), Scale(dual_, scale));
}

Eigen::Matrix<double, 8, 1> DualQuaternion::ToVector() const {
  Eigen::Matrix<double, 8, 1> v;
  v << real_.w(), real_.x(), real_.y(), real_.z(), dual_.w(), dual_.x(), dual_.y(), dual_.z();
  return v;
}

DualQuaternion DualQuaternion::FromVector(const Eigen::Matrix<double, 8, 1>& v) {
  return DualQuaternion(Eigen::Quaterniond(v(0), v(1), v(2), v(3)),
                        Eigen::Quaterniond(v(4), v(5), v(6), v(7)));
}

bool DualQuaternion::IsSamePose(const DualQuaternion& other, double tolerance) const {
  const Eigen::Matrix<double, 8, 1> a = ToVector();
  const Eigen::Matrix<double, 8, 1> b = other.ToVector();
  return (a - b).cwiseAbs().maxCoeff() <= tolerance || (a + b).cwiseAbs().maxCoeff() <= tolerance;
}

}  // namespace hecal
