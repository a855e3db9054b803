// The translation step of the AX = ZB solvers on absolute poses (Shah; Li's re-solve): with
// R_X and R_Z known, the translation part of Z = A_i X B_i (problem.h) is
//        t_Z − R_Ai t_X = R_Ai R_X t_Bi + t_Ai =: d_i,
// linear in (t_X, t_Z). Least squares over the stations, with the 6×6 normal equations
//        [ n I      −Mᵀ ] [t_X]   [ −Σ R_Aiᵀ d_i ]
//        [ −M       n I ] [t_Z] = [   Σ d_i      ],      M = Σ R_Ai,
// solved through the 3×3 Schur complement n I − MᵀM / n (no matrix grows with n). The
// complement is singular exactly when one direction is fixed by every R_Aj⁻¹ R_Ai (all relative
// rotations about parallel axes, or pure translations): then t_X along that axis trades off
// against t_Z and DegenerateError is thrown.
#pragma once

#include <Eigen/Core>

#include "hecal/handeye/problem.h"

namespace hecal::handeye {

// Smallest eigenvalue of the Schur complement, relative to n, below which the translations are
// not determined.
inline constexpr double kTranslationXZMinConditioning = 1e-12;

struct TranslationsXZ {
  Eigen::Vector3d t_X;
  Eigen::Vector3d t_Z;
};

// Requires problem.A.size() == problem.B.size() >= 1.
TranslationsXZ SolveTranslationsXZ(const Problem& problem, const Eigen::Matrix3d& R_X);

}  // namespace hecal::handeye
