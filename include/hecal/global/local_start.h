// A fast local estimate of X = T_hand_camera for the global search (branch_and_bound.h): its
// incumbent, and the point at which outlier_removal.h measures the data's own error level.
// Heller, Havlena, Pajdla (TPAMI 38(5), 2016, §5) start the search from such a local solution.
//
// 1. Per motion, R_A from the essential matrix of its pairs (essential_matrix.h).
// 2. R_A = Rᵀ R_B R gives, for the rotation vectors α = Log R_A and β = Log R_B, β = R α (Park &
//    Martin 1994, eq. 5); R = argmin Σ |β − R α|² is the nearest rotation to Σ β αᵀ (Kabsch,
//    nearest_rotation.h). Motions whose hand rotation is below 1° are skipped (their axis is
//    noise).
// 3. t at that R (BestTranslation): bisection on ε in [0, high] over the per-cube linear
//    programme of cube_feasibility.h with a zero-width cube (one rotation), keeping the t of
//    smallest max E — the L∞ translation for R to the precision of the pyramid relaxation.
// nullopt when fewer than two motions give a rotation or their axes are parallel (then the
// search starts without an incumbent).
#pragma once

#include <Eigen/Core>
#include <optional>

#include "hecal/global/epipolar_problem.h"

namespace hecal::global {

// translation_bound: |t_k| ≤ T (metres), as in the search.
std::optional<Pose> LocalStart(const EpipolarProblem& problem, double translation_bound);

struct FixedRotationFit {
  Pose X = Pose::Identity();
  double error = 0.0;  // max E at X
  int lps = 0;         // GLPK calls
};

// Step 3 for a given R: `iterations` bisection steps on ε in [0, high]; `hint` is the first
// translation tried (and the answer when no step does better).
FixedRotationFit BestTranslation(const EpipolarProblem& problem, const Eigen::Matrix3d& R,
                                 double translation_bound, double high, int iterations,
                                 const Eigen::Vector3d& hint = Eigen::Vector3d::Zero());

}  // namespace hecal::global
