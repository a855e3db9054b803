// The per-cube test of the branch-and-bound (Heller, Havlena, Pajdla, CVPR 2012 §4 / TPAMI 2016
// §4, after Hartley & Kahl, "Global optimization through rotation space search", IJCV 2009): can
// any X = (R, t) with R = Exp(r), r in the cube |r − r̄|∞ ≤ σ, and |t| ≤ T reach max E ≤ ε?
// A "no" is proved by an infeasible linear programme; a "maybe" returns the LP's point.
//
// Notation as in epipolar_problem.h: t_A = Rᵀ w with w = (R_B − I) t + t_B, linear in t (the
// unknown of the LP, |t_k| ≤ T) and free of R. E ≤ ε puts t_A in the convex cone
// cone(C(v, ε) ∪ C(−R_A u, ε)); rotated into the hand frame by R (and R R_A = R_B R), w lies in
// cone(C(R v, ε) ∪ C(−R_B R u, ε)). The rotation enters only through the two rays: with
// δ = √3 σ bounding the angle between Exp(r) and R̄ = Exp(r̄) (Hartley–Kahl Lemma 1), R v is
// within δ of R̄ v and R_B R u within δ of R_B R̄ u, so for every R in the cube
//   w ∈ K = cone(C(R̄ v, ε + δ) ∪ C(−R_B R̄ u, ε + δ)).
// Every unit q with q·x ≤ 0 on both caps gives the necessary condition q·w ≤ 0, one LP row
//   qᵀ(R_B − I) t ≤ −q·t_B.
// Writing the cone in the hand frame is what keeps the bound tight: in the camera frame (the
// paper's form) the rotation uncertainty also moves t_A itself, by up to
// 8 sin(β/2) sin(δ/2)·T, a slack that grows with the search radius T and that needs cubes far
// smaller than ε before they can be pruned when the matches are noisy.
// We use the two planes tangent to both caps and the plane tangent to each cap at its far side
// (a pyramid around the wedge). A pair whose caps reach each other round the back (the rays
// nearly parallel within the widened tolerance) gives no row; that only weakens the test.
// The programme has 3 unknowns and ≤ 4 rows per pair; a failure of the solver counts as
// "maybe", so pruning is never wrong because of it.
#pragma once

#include <Eigen/Core>
#include <optional>

#include "hecal/global/epipolar_problem.h"

namespace hecal::global {

struct CubeQuery {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // r̄, rotation vector of R (X's rotation)
  double half_width = 0.0;                           // σ (radians); 0 tests the rotation R̄ alone
  double epsilon = 0.0;                              // ε (radians)
  double translation_bound = 1.0;                    // T (metres): |t| ≤ T
};

// nullopt: no X in the cube reaches max E ≤ ε (proved). Otherwise the translation t of a point
// satisfying every row (a candidate to evaluate, not a guarantee). The programme is
// solved by cutting planes: GLPK on the rows the current point violates most, adding violated
// rows until none is (feasible) or the subset is infeasible (then so is the whole). `hint` (a
// translation, e.g. the parent cube's) is the first point tried; `lps` counts GLPK calls.
std::optional<Eigen::Vector3d> TestCube(const EpipolarProblem& problem, const CubeQuery& query,
                                        const Eigen::Vector3d& hint = Eigen::Vector3d::Zero(),
                                        int* lps = nullptr);

}  // namespace hecal::global
