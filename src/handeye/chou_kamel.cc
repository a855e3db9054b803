#include "hecal/handeye/chou_kamel.h"

#include <Eigen/QR>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <optional>

#include "hecal/core/error.h"
#include "hecal/geometry/quaternion_matrices.h"
#include "hecal/geometry/rotation.h"
#include "hecal/handeye/observability.h"
#include "hecal/handeye/rotation_init.h"
#include "hecal/handeye/translation.h"

namespace hecal::handeye {
namespace {

// The rotation angle 2 atan2(|a_v|, |a_w|) ∈ [0, π] of a unit quaternion.
double Angle(const Eigen::Quaterniond& a) {
  return 2.0 * std::atan2(a.vec().norm(), std::abs(a.w()));
}

// Motions per Householder QR: the 4×4 factor R and kBatch blocks B_i are stacked and reduced
// together (one QR of a (4 + 4·kBatch)×4 matrix costs far less than kBatch QRs of 8×4).
constexpr int kBatch = 16;

// Solves the stacked system (CK) over the motions rotating by at least min_angle; nullopt when
// they do not determine q (smallest singular value not separated).
std::optional<Eigen::Matrix3d> SolveStackedSystem(const std::vector<AlignedQuaternions>& motions,
                                                  double min_angle) {
  using Stack = Eigen::Matrix<double, 4 + 4 * kBatch, 4>;
  Stack stack = Stack::Zero();  // rows 0–3: R so far; then up to kBatch blocks B_i
  Eigen::HouseholderQR<Stack> qr;
  int filled = 0;
  const auto reduce = [&]() {
    qr.compute(stack);
    stack.topRows<4>() = qr.matrixQR().topRows<4>().triangularView<Eigen::Upper>();
    stack.bottomRows<4 * kBatch>().setZero();
    filled = 0;
  };
  for (const AlignedQuaternions& q : motions) {
    if (Angle(q.a) < min_angle) continue;
    const double norm_a = q.a.vec().norm();
    const double norm_b = q.b.vec().norm();
    if (norm_a == 0.0 || norm_b == 0.0) continue;
    const Eigen::Vector4d k_A(0.0, q.a.x() / norm_a, q.a.y() / norm_a, q.a.z() / norm_a);
    const Eigen::Vector4d k_B(0.0, q.b.x() / norm_b, q.b.y() / norm_b, q.b.z() / norm_b);
    stack.block<4, 4>(4 + 4 * filled, 0) = QuaternionLeftMatrix(k_A) - QuaternionRightMatrix(k_B);
    if (++filled == kBatch) reduce();
  }
  if (filled > 0) reduce();
  const Eigen::JacobiSVD<Eigen::Matrix4d> svd(stack.topRows<4>(), Eigen::ComputeFullV);
  const Eigen::Vector4d& sigma = svd.singularValues();  // descending
  if (!(sigma(2) > 1e-9 * sigma(0))) return std::nullopt;
  return MatrixFromQuaternion(FromWxyz(svd.matrixV().col(3)));
}

}  // namespace

Pose SolveChouKamel(const std::vector<Motion>& motions) {
  const Eigen::Matrix3d R0 = SignFreeRotation(motions);
  std::vector<AlignedQuaternions> aligned;
  aligned.reserve(motions.size());
  double max_angle = 0.0;
  for (const Motion& motion : motions) {
    aligned.push_back(AlignQuaternions(motion, R0));
    max_angle = std::max(max_angle, Angle(aligned.back().a));
  }
  std::optional<Eigen::Matrix3d> R_X =
      SolveStackedSystem(aligned, std::max(kMinRotation, kChouKamelMinAngleFraction * max_angle));
  if (!R_X) R_X = SolveStackedSystem(aligned, kMinRotation);
  if (!R_X) {
    throw DegenerateError(
        "the hand-eye rotation about the common rotation axis (Chou-Kamel: the stacked "
        "quaternion system has rank < 3, every motion rotates about parallel axes)",
        "add stations whose relative rotations have clearly different axes");
  }
  return MakePose(*R_X, SolveTranslation(motions, *R_X));
}

}  // namespace hecal::handeye
