// Eigen's dense decompositions on the matrix types hecal factors in many places, compiled once in
// the geometry library (src/geometry/dense_decompositions.cc, dense_decompositions_12.cc: one
// file each, so that neither is a long compile) instead of in every file that uses
// them. A decomposition class template is instantiated by each translation unit that names it —
// several seconds of compile time per type and file for the SVD and the rank-revealing QR — unless
// an explicit instantiation declaration (`extern template`, C++ [temp.explicit]) says that one
// object file already holds it. Include this header wherever one of these types is used; the
// calls are unchanged, only the instantiation moves (docs/build.md#build-time).
//
// Covered: the dynamic-size Eigen::MatrixXd forms of JacobiSVD, ColPivHouseholderQR and
// CompleteOrthogonalDecomposition, and the 12 × 12 complete
// orthogonal decomposition of the hand–eye normal equations (the pseudo-inverse of ml, the model
// check and the noise estimation). For these classes the factorisation is a non-template member
// (compute(const MatrixType&) or computeInPlace()), so the declaration below keeps it out of the
// including file; the small templated wrappers (solve(), the compute(EigenBase) overloads) are
// still instantiated where used, and are cheap. A fixed-size type that only a hot inner loop uses
// (3 × 3, 6 × 6 per station) stays inline where it is.
//
// The functions below are the uses that also instantiate heavy templated members (the
// pseudo-inverse evaluates a solve against the identity): each is exactly the Eigen expression it
// names, compiled once.
#pragma once

#include <Eigen/Core>
#include <Eigen/QR>
#include <Eigen/SVD>

extern template class Eigen::JacobiSVD<Eigen::MatrixXd>;
extern template class Eigen::ColPivHouseholderQR<Eigen::MatrixXd>;
extern template class Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>;
extern template class Eigen::ColPivHouseholderQR<Eigen::Matrix<double, 12, 12>>;
extern template class Eigen::CompleteOrthogonalDecomposition<Eigen::Matrix<double, 12, 12>>;

namespace hecal {

// M⁺ by a complete orthogonal decomposition with Eigen's default rank threshold:
// M.completeOrthogonalDecomposition().pseudoInverse().
Eigen::MatrixXd PseudoInverse(const Eigen::MatrixXd& M);
Eigen::Matrix<double, 12, 12> PseudoInverse12(const Eigen::Matrix<double, 12, 12>& M);

// The minimum-norm least-squares solution of M x = b by the same decomposition:
// M.completeOrthogonalDecomposition().solve(b).
Eigen::Matrix<double, 12, 1> PseudoSolve12(const Eigen::Matrix<double, 12, 12>& M,
                                           const Eigen::Matrix<double, 12, 1>& b);

// The least-squares solution of A x = b by column-pivoting Householder QR:
// A.colPivHouseholderQr().solve(b).
Eigen::VectorXd ColPivQrSolve(const Eigen::MatrixXd& A, const Eigen::VectorXd& b);

}  // namespace hecal
