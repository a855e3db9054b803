// The per-cube test of the branch-and-bound (Heller, Havlena, Pajdla, CVPR 2012 §4 / TPAMI 2016
// §4, after Hartley & Kahl, "Global optimization through rotation space search", IJCV 2009): can
// any X = (R, t) with R = Exp(r), r in the cube |r − r̄|∞ ≤ σ, and |t| ≤ T reach max E ≤ ε?
// A "no" is proved by an infeasible linear programme; a "maybe" returns the LP's point.
//
// Notation as in epipolar_problem.h. With s = Rᵀt (the unknown of the LP, |s_k| ≤ T) the camera
// motion is R_A = Rᵀ R_B R and t_A = (R_A − I) s + Rᵀ t_B, linear in s (paper eq. 2).
// Rotation uncertainty (δ = √3 σ bounds the angle between Exp(r) and R̄ = Exp(r̄), Hartley–Kahl
// Lemma 1), with β the angle of R_B:
//   |R_A − R̄_A| ≤ 2 |R_B − I| |Rᵀ R̄ − I| = 8 sin(β/2) sin(δ/2) =: η_A        (paper's (11):
//                                                     2‖β‖ sin(√3σ/2) to first order),
//   so R_A u lies within γ = 2 asin(η_A / 2) of R̄_A u, and
//   t_A = t̄_A(s) + Δ,  t̄_A(s) = (R̄_A − I) s + R̄ᵀ t_B,  |Δ| ≤ η_A T + 2 sin(δ/2) |t_B| =: r.
// E ≤ ε puts t_A in the convex cone K = cone(C(v, ε) ∪ C(−R̄_A u, ε + γ)) (the "pair of
// ε-epipolar cones"). Every unit q with q·x ≤ 0 on both caps gives the necessary condition
//   q·t̄_A(s) ≤ r        (one LP row: qᵀ(R̄_A − I) s ≤ r − q·R̄ᵀ t_B).
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

// nullopt: no X in the cube reaches max E ≤ ε (proved). Otherwise the translation t = R̄ s of
// a point satisfying every row (a candidate to evaluate, not a guarantee). The programme is
// solved by cutting planes: GLPK on the rows the current point violates most, adding violated
// rows until none is (feasible) or the subset is infeasible (then so is the whole). `hint` (a
// translation, e.g. the parent cube's) is the first point tried; `lps` counts GLPK calls.
std::optional<Eigen::Vector3d> TestCube(const EpipolarProblem& problem, const CubeQuery& query,
                                        const Eigen::Vector3d& hint = Eigen::Vector3d::Zero(),
                                        int* lps = nullptr);

}  // namespace hecal::global
