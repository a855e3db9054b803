// Internal: the per-station 6×6 and 6×12 kernels of the ml solver (loop_solver.h), the noise
// estimation and the station tests (noise_estimation.h), written as fixed-size coefficient loops.
// Why not Eigen's expressions: Eigen sends a product whose three sizes add up to more than 20
// (EIGEN_GEMM_TO_COEFFBASED_THRESHOLD: 6 × 6 times 6 × 12, 6 × 12 times 12 × 12), a triangular
// solve against a matrix and a selfadjoint rank update through its blocked kernels for large
// dynamic matrices, which at these sizes spend several times the arithmetic on packing and
// dispatch: at n = 50 the 12 × 12 rank update alone was 45% of a Gauss–Newton linearisation and
// the 6 × 6 triangular solves 1.8 M instructions per `hecal bench --stations 50 --method ml`
// calibration (callgrind; docs/bench.md).
#pragma once

#include <Eigen/Core>

namespace hecal::estimation::internal {

// L⁻¹ of a lower-triangular 6 × 6 L with a non-zero diagonal (only the lower triangle of
// `lower` is read, e.g. Eigen::LLT::matrixLLT()), by forward substitution.
inline Eigen::Matrix<double, 6, 6> LowerTriangularInverse(
    const Eigen::Matrix<double, 6, 6>& lower) {
  Eigen::Matrix<double, 6, 6> inverse = Eigen::Matrix<double, 6, 6>::Zero();
  for (int c = 0; c < 6; ++c) {
    inverse(c, c) = 1.0 / lower(c, c);
    for (int r = c + 1; r < 6; ++r) {
      double sum = 0.0;
      for (int k = c; k < r; ++k) sum += lower(r, k) * inverse(k, c);
      inverse(r, c) = -sum / lower(r, r);
    }
  }
  return inverse;
}

// H += w · Mᵀ M for a 6 × 12 M (the Gauss–Newton information of one whitened station): the 78
// column products of the upper triangle, each written to both halves (exactly symmetric).
inline void AddWeightedGram(const Eigen::Matrix<double, 6, 12>& M, double w,
                            Eigen::Matrix<double, 12, 12>* H) {
  for (int j = 0; j < 12; ++j) {
    for (int i = 0; i < j; ++i) {
      const double value = w * M.col(i).dot(M.col(j));
      (*H)(i, j) += value;
      (*H)(j, i) += value;
    }
    (*H)(j, j) += w * M.col(j).squaredNorm();
  }
}

}  // namespace hecal::estimation::internal
