// The certificate of global optimality of certificate.h.
#include "hecal/handeye/certificate.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "hecal/geometry/skew.h"
#include "hecal/geometry/so3.h"
#include "hecal/handeye/kronecker.h"

namespace hecal::handeye {
namespace {

// z = (vec R_X, vec R_Z, y, t_X, t_Z): the rotations and y first, so that the reduced r is the
// leading 19 entries.
constexpr int kFull = 25;
constexpr int kReduced = 19;
constexpr int kY = 18;
using Matrix25d = Eigen::Matrix<double, kFull, kFull>;
using Matrix19d = Eigen::Matrix<double, kReduced, kReduced>;
using Vector19d = Eigen::Matrix<double, kReduced, 1>;

// zᵀ Q z is the cost of certificate.h.
Matrix25d CostMatrix(const Problem& problem, const ChordalWeights& weights) {
  Matrix25d Q = Matrix25d::Zero();
  for (size_t i = 0; i < problem.A.size(); ++i) {
    const Eigen::Matrix3d R_A = problem.A[i].linear();
    const Eigen::Matrix3d R_B = problem.B[i].linear();
    const Eigen::Vector3d t_B = problem.B[i].translation();
    Eigen::Matrix<double, 9, kFull> rotation = Eigen::Matrix<double, 9, kFull>::Zero();
    Eigen::Matrix<double, 3, kFull> translation = Eigen::Matrix<double, 3, kFull>::Zero();
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 3; ++k) {
        // vec(R_A R_X R_B) = (R_Bᵀ ⊗ R_A) vec(R_X)
        rotation.block<3, 3>(3 * k, 3 * j) = R_B(j, k) * R_A;
      }
      translation.block<3, 3>(0, 3 * j) = t_B(j) * R_A;  // R_A R_X t_B = (t_Bᵀ ⊗ R_A) vec R_X
    }
    rotation.block<9, 9>(0, 9) = -Eigen::Matrix<double, 9, 9>::Identity();
    translation.col(kY) = problem.A[i].translation();
    translation.block<3, 3>(0, 19) = R_A;
    translation.block<3, 3>(0, 22) = -Eigen::Matrix3d::Identity();
    Q.noalias() += weights.rotation * rotation.transpose() * rotation;
    Q.noalias() += weights.translation * translation.transpose() * translation;
  }
  return Q;
}

Vector19d Reduced(const Eigen::Matrix3d& R_X, const Eigen::Matrix3d& R_Z) {
  Vector19d r;
  r << Vec(R_X), Vec(R_Z), 1.0;
  return r;
}

// Gauss–Newton on SO(3) × SO(3) for min rᵀ Q_r r, Q_r = Lᵀ L; returns (R_X, R_Z).
std::pair<Eigen::Matrix3d, Eigen::Matrix3d> Polish(const Matrix19d& Q_r, Eigen::Matrix3d R_X,
                                                   Eigen::Matrix3d R_Z) {
  const Eigen::SelfAdjointEigenSolver<Matrix19d> eigen(Q_r);
  const Matrix19d L =
      eigen.eigenvalues().cwiseMax(0.0).cwiseSqrt().asDiagonal() * eigen.eigenvectors().transpose();
  const auto cost = [&](const Eigen::Matrix3d& X, const Eigen::Matrix3d& Z) {
    return (L * Reduced(X, Z)).squaredNorm();
  };
  double current = cost(R_X, R_Z);
  for (int iteration = 0; iteration < 100; ++iteration) {
    Eigen::Matrix<double, kReduced, 6> J = Eigen::Matrix<double, kReduced, 6>::Zero();
    for (int k = 0; k < 3; ++k) {
      const Eigen::Matrix3d G = Skew(Eigen::Vector3d::Unit(k));
      J.block<9, 1>(0, k) = Vec(R_X * G);
      J.block<9, 1>(9, 3 + k) = Vec(R_Z * G);
    }
    const Eigen::Matrix<double, kReduced, 6> LJ = L * J;
    const Eigen::Matrix<double, 6, 1> step =
        -(LJ.transpose() * LJ).ldlt().solve(LJ.transpose() * (L * Reduced(R_X, R_Z)));
    if (!step.allFinite()) break;
    double length = 1.0;
    while (length > 1e-6) {
      const Eigen::Matrix3d X = R_X * so3::Exp(length * step.head<3>());
      const Eigen::Matrix3d Z = R_Z * so3::Exp(length * step.tail<3>());
      const double next = cost(X, Z);
      if (next <= current) {
        const bool converged = current - next <= 1e-15 * current || step.norm() * length < 1e-13;
        R_X = X;
        R_Z = Z;
        current = next;
        if (converged) return {R_X, R_Z};
        break;
      }
      length /= 2;
    }
    if (length <= 1e-6) break;
  }
  return {R_X, R_Z};
}

}  // namespace

ChordalWeights WeightsFromSigmas(double rotation_sigma, double translation_sigma,
                                 double length_scale) {
  const double rotation = std::max(rotation_sigma, 1e-9);
  const double translation = std::sqrt(translation_sigma * translation_sigma +
                                       rotation * rotation * length_scale * length_scale);
  return {1.0 / (rotation * rotation), 1.0 / std::max(translation * translation, 1e-18)};
}

Certificate CertifyGlobalOptimum(const Problem& problem, const Solution& answer,
                                 const ChordalWeights& weights) {
  if (problem.A.size() < 2 || problem.A.size() != problem.B.size()) {
    throw std::invalid_argument("CertifyGlobalOptimum: needs two or more stations");
  }
  const Matrix25d Q = CostMatrix(problem, weights);
  // The translations in closed form: t = −Q_tt⁻¹ Q_tr r, Q_r = Q_rr − Q_rt Q_tt⁻¹ Q_tr.
  const Eigen::Matrix<double, 6, 6> Q_tt = Q.bottomRightCorner<6, 6>();
  const Eigen::Matrix<double, 6, kReduced> Q_tr = Q.bottomLeftCorner<6, kReduced>();
  const Eigen::CompleteOrthogonalDecomposition<Eigen::Matrix<double, 6, 6>> tt(Q_tt);
  const Eigen::Matrix<double, 6, kReduced> translation_of = -tt.solve(Q_tr);
  Matrix19d Q_r = Q.topLeftCorner<kReduced, kReduced>() + Q_tr.transpose() * translation_of;
  Q_r = 0.5 * (Q_r + Q_r.transpose()).eval();

  Certificate certificate;
  const auto [R_X, R_Z] = Polish(Q_r, answer.X.linear(), answer.Z.linear());
  const Vector19d r = Reduced(R_X, R_Z);
  const Eigen::Matrix<double, 6, 1> t = translation_of * r;
  certificate.polished.X = MakePose(R_X, t.head<3>());
  certificate.polished.Z = MakePose(R_Z, t.tail<3>());
  certificate.cost = r.dot(Q_r * r);

  // Stationarity: Σ_k λ_k A_k r + ρ e_y y = Q_r r, with A_k the column constraints
  // c_jᵀ c_k − δ_jk y² of each rotation (S_jk ⊗ I₃ in its block, −δ_jk at (y, y)).
  std::vector<Matrix19d> constraints;
  for (int block = 0; block < 2; ++block) {
    for (int j = 0; j < 3; ++j) {
      for (int k = j; k < 3; ++k) {
        Matrix19d A = Matrix19d::Zero();
        const int a = 9 * block + 3 * j, b = 9 * block + 3 * k;
        A.block<3, 3>(a, b) += Eigen::Matrix3d::Identity();
        if (j != k) A.block<3, 3>(b, a) += Eigen::Matrix3d::Identity();
        if (j == k) A(kY, kY) = -1.0;
        constraints.push_back(A);
      }
    }
  }
  Matrix19d E_yy = Matrix19d::Zero();
  E_yy(kY, kY) = 1.0;
  constraints.push_back(E_yy);  // ρ, the multiplier of y² = 1
  Eigen::Matrix<double, kReduced, 13> columns;
  for (int k = 0; k < 13; ++k) columns.col(k) = constraints[static_cast<size_t>(k)] * r;
  const Vector19d target = Q_r * r;
  const Eigen::Matrix<double, 13, 1> multipliers =
      columns.completeOrthogonalDecomposition().solve(target);
  Matrix19d H = Q_r;
  for (int k = 0; k < 13; ++k) H -= multipliers(k) * constraints[static_cast<size_t>(k)];
  certificate.lower_bound = multipliers(12);
  certificate.gap = certificate.cost - certificate.lower_bound;
  const Eigen::SelfAdjointEigenSolver<Matrix19d> H_eigen(0.5 * (H + H.transpose()),
                                                         Eigen::EigenvaluesOnly);
  const double scale =
      std::max(Eigen::SelfAdjointEigenSolver<Matrix19d>(Q_r, Eigen::EigenvaluesOnly)
                   .eigenvalues()
                   .maxCoeff(),
               1e-300);
  certificate.stationarity = (H * r).norm() / (scale * r.norm());
  certificate.min_eigenvalue = H_eigen.eigenvalues().minCoeff() / scale;
  certificate.certified = certificate.min_eigenvalue >= -kCertificateEigenTolerance &&
                          certificate.stationarity <= kCertificateStationarityTolerance;

  certificate.distance_rotation = std::max(so3::Log(answer.X.linear().transpose() * R_X).norm(),
                                           so3::Log(answer.Z.linear().transpose() * R_Z).norm());
  certificate.distance_translation = std::max((answer.X.translation() - t.head<3>()).norm(),
                                              (answer.Z.translation() - t.tail<3>()).norm());
  return certificate;
}

}  // namespace hecal::handeye
