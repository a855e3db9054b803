// The one instantiation of the dynamic-size decompositions that dense_decompositions.h declares
// extern, and its functions on them.
#include "hecal/geometry/dense_decompositions.h"

template class Eigen::JacobiSVD<Eigen::MatrixXd>;
template class Eigen::ColPivHouseholderQR<Eigen::MatrixXd>;
template class Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>;

namespace hecal {

Eigen::MatrixXd PseudoInverse(const Eigen::MatrixXd& M) {
  return M.completeOrthogonalDecomposition().pseudoInverse();
}

Eigen::VectorXd ColPivQrSolve(const Eigen::MatrixXd& A, const Eigen::VectorXd& b) {
  return A.colPivHouseholderQr().solve(b);
}

}  // namespace hecal
