// The one instantiation of the 12 × 12 decompositions that dense_decompositions.h declares extern,
// and its functions on them.
#include "hecal/geometry/dense_decompositions.h"

template class Eigen::ColPivHouseholderQR<Eigen::Matrix<double, 12, 12>>;
template class Eigen::CompleteOrthogonalDecomposition<Eigen::Matrix<double, 12, 12>>;

namespace hecal {

Eigen::Matrix<double, 12, 12> PseudoInverse12(const Eigen::Matrix<double, 12, 12>& M) {
  return M.completeOrthogonalDecomposition().pseudoInverse();
}

Eigen::Matrix<double, 12, 1> PseudoSolve12(const Eigen::Matrix<double, 12, 12>& M,
                                           const Eigen::Matrix<double, 12, 1>& b) {
  return M.completeOrthogonalDecomposition().solve(b);
}

}  // namespace hecal
