#include "hecal/global/essential_matrix.h"

#include <Eigen/SVD>
#include <cmath>

#include "hecal/geometry/dense_decompositions.h"

namespace hecal::global {

double SampsonError(const Eigen::Matrix3d& E, const BearingPair& pair) {
  const Eigen::Vector3d v = pair.first.normalized(), u = pair.second.normalized();
  const Eigen::Vector3d Eu = E * u, Etv = E.transpose() * v;
  const double scale =
      std::sqrt((Eu - v * v.dot(Eu)).squaredNorm() + (Etv - u * u.dot(Etv)).squaredNorm());
  return scale > 0 ? std::abs(v.dot(Eu)) / scale : M_PI / 2;
}

Eigen::Matrix3d EightPoint(const std::vector<BearingPair>& pairs, const std::vector<int>& sample) {
  Eigen::MatrixXd A(sample.size(), 9);
  for (std::size_t k = 0; k < sample.size(); ++k) {
    const Eigen::Vector3d v = pairs[sample[k]].first, u = pairs[sample[k]].second;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) A(k, 3 * i + j) = v[i] * u[j];
    }
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeFullV);
  const Eigen::VectorXd e = svd.matrixV().col(8);
  Eigen::Matrix3d E;
  E << e[0], e[1], e[2], e[3], e[4], e[5], e[6], e[7], e[8];
  return E;
}

std::optional<Eigen::Matrix3d> RotationFromEssential(const std::vector<BearingPair>& pairs) {
  if (pairs.size() < 8) return std::nullopt;
  std::vector<int> all(pairs.size());
  for (std::size_t i = 0; i < pairs.size(); ++i) all[i] = int(i);
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(EightPoint(pairs, all),
                                              Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d U = svd.matrixU(), V = svd.matrixV();
  if (U.determinant() < 0) U = -U;
  if (V.determinant() < 0) V = -V;
  Eigen::Matrix3d W;
  W << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  std::optional<Eigen::Matrix3d> best;
  int best_count = -1;
  for (const Eigen::Matrix3d& R : {Eigen::Matrix3d(U * W * V.transpose()),
                                   Eigen::Matrix3d(U * W.transpose() * V.transpose())}) {
    for (const double sign : {1.0, -1.0}) {
      const Eigen::Vector3d t = sign * U.col(2);
      int count = 0;
      for (const BearingPair& pair : pairs) {
        // λ v − μ R u = t in least squares.
        Eigen::Matrix<double, 3, 2> M;
        M.col(0) = pair.first.normalized();
        M.col(1) = -(R * pair.second.normalized());
        const Eigen::Vector2d depth = M.colPivHouseholderQr().solve(t);
        count += depth[0] > 0 && depth[1] > 0;
      }
      if (count > best_count) {
        best_count = count;
        best = R;
      }
    }
  }
  return best;
}

}  // namespace hecal::global
