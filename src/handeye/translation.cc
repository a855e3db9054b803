// The shared translation step (translation.h). Every motion contributes the rows
//        (R_A − I) t = R_X t_B − t_A                                                (T1)
// and the least-squares solution satisfies the 3×3 normal equations N t = g with
//        N = Σ (R_A − I)ᵀ(R_A − I) = Σ (2I − R_A − R_Aᵀ)       (R_Aᵀ R_A = I)
//        g = Σ (R_A − I)ᵀ (R_X t_B − t_A).
// For a rotation by θ about the unit axis n, 2I − R − Rᵀ = 2(1 − cos θ)(I − n nᵀ): each motion
// constrains t only across its own axis, with weight 4 sin²(θ/2). So near-zero rotations add
// (almost) nothing, rotations near π add the most, and N is singular exactly when all axes are
// parallel (no information along the common axis) or no motion rotates at all.
#include "hecal/handeye/translation.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <string>

#include "hecal/core/error.h"
#include "hecal/handeye/observability.h"

namespace hecal::handeye {
namespace {

// N is numerically singular when its smallest eigenvalue is below this fraction of the largest.
constexpr double kRelativeSingularity = 1e-12;

// The normal equations N t = g of (T1).
void Accumulate(const std::vector<Motion>& motions, const Eigen::Matrix3d& R_X,
                Eigen::Matrix3d* N, Eigen::Vector3d* g) {
  N->setZero();
  g->setZero();
  for (const Motion& motion : motions) {
    const Eigen::Matrix3d& R_A = motion.A.linear();
    const Eigen::Vector3d rhs = R_X * motion.B.translation() - motion.A.translation();
    *N -= R_A + R_A.transpose();
    N->diagonal().array() += 2.0;
    g->noalias() += R_A.transpose() * rhs - rhs;
  }
}

}  // namespace

Eigen::Vector3d SolveTranslation(const std::vector<Motion>& motions, const Eigen::Matrix3d& R_X) {
  Eigen::Matrix3d N;
  Eigen::Vector3d g;
  Accumulate(motions, R_X, &N, &g);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(N);
  const Eigen::Vector3d& lambda = eigen.eigenvalues();  // ascending
  // The mean of 4 sin²(θ/2) over the motions is λ₁ + λ₂ + λ₃ over 2 per motion; below the square
  // of kMinRotation the robot has only translated.
  const double count = static_cast<double>(motions.size());
  if (motions.empty() || lambda.sum() < 2.0 * count * kMinRotation * kMinRotation) {
    throw DegenerateError("the translation of X (no motion rotates: the robot only translated)",
                          "rotate the robot between stations about at least two different axes");
  }
  if (lambda(0) <= kRelativeSingularity * lambda(2)) {
    const Eigen::Vector3d axis = eigen.eigenvectors().col(0);
    throw DegenerateError("the translation of X along the common rotation axis (" +
                              std::to_string(axis.x()) + ", " + std::to_string(axis.y()) + ", " +
                              std::to_string(axis.z()) +
                              "): every motion rotates about parallel axes",
                          "add stations whose relative rotations have clearly different axes");
  }
  // t = V Λ⁻¹ Vᵀ g with the decomposition already at hand.
  return eigen.eigenvectors() * (eigen.eigenvectors().transpose() * g).cwiseQuotient(lambda);
}

Eigen::Vector3d SolveTranslation(const std::vector<Motion>& motions, const Eigen::Matrix3d& R_X,
                                 const TranslationFix& fix) {
  Eigen::Matrix3d N;
  Eigen::Vector3d g;
  Accumulate(motions, R_X, &N, &g);
  // [N e; eᵀ 0] [t; μ] = [g; value].
  Eigen::Matrix4d K = Eigen::Matrix4d::Zero();
  K.topLeftCorner<3, 3>() = N;
  K(fix.axis, 3) = K(3, fix.axis) = 1.0;
  Eigen::Vector4d rhs;
  rhs << g, fix.value;
  Eigen::FullPivLU<Eigen::Matrix4d> lu(K);
  lu.setThreshold(kRelativeSingularity);
  if (!lu.isInvertible()) {
    throw DegenerateError("the translation of X, even with " + ComponentName(fix.axis) +
                              " given: the robot does not rotate, or rotates about an axis "
                              "perpendicular to " + ComponentName(fix.axis),
                          "fix the component along the robot's rotation axis");
  }
  return lu.solve(rhs).head<3>();
}

}  // namespace hecal::handeye
