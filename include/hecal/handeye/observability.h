// Degeneracy checks run before any solver: degenerate input gives a clear error naming the
// unobservable part (exit 2), never a silent number.
//
// From motions A_ij X = X B_ij:
//  - fewer than 3 stations                         → nothing can be estimated reliably
//  - every motion is a pure translation (angle of A_ij below kMinRotation): R_X is still fixed
//    by the translation directions, but the translation of X is not observable
//  - all rotation axes of A_ij parallel (within kParallelAxes): rotation of X about that axis
//    direction is still fixed by translations in general, but the translation of X along the
//    common axis is not observable (Tsai & Lenz 1989, Shiu & Ahmad 1989: two non-parallel axes
//    are required)
// Thresholds are on the robot side (A), whose motions the user chose.
//
// Under noise the exact checks above are not enough: robot rotation noise σ spreads parallel
// axes and turns pure translations into tiny rotations, and the solvers then return a number
// whose translation along the unobservable direction is pure noise (measured: 0.3° / 0.3 mm
// noise on 15 stations spinning about one axis gave an X 22 cm off with a first-order 1σ of
// 2.6 cm — the linearisation is meaningless there). CheckObservabilityUnderNoise compares the
// translation normal matrix N (observability.cc, (O1)) with what noise alone puts into it: a
// pair of stations whose rotations differ only by noise adds E[2I − R − Rᵀ] = 4σ² I (each
// relative rotation carries 2σ² per axis), so pure noise gives N ≈ P · 4σ² I over P pairs.
// The ratio ρ = λ(N) / (P · 4σ²) is ≈ 1 along a direction that only noise observes; real
// data sets have ρ_min in the thousands (moveit-calibration 1.8e5, tabb-rwhe-dataset1 ~600 with
// its estimated noise). ρ_min < kNoiseDegenerate is an error, ρ_min < kNoiseWeak a warning.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "hecal/handeye/motion.h"
#include "hecal/handeye/problem.h"

namespace hecal::handeye {

inline constexpr double kMinRotation = 1e-3;   // rad: below this a motion is a translation
inline constexpr double kParallelAxes = 1e-3;  // rad: spread of axes below this is parallel

inline constexpr double kNoiseDegenerate = 3.0;  // ρ_min below this: not observable
inline constexpr double kNoiseWeak = 20.0;       // ρ_min below this: weakly observable

// (O1) of observability.cc: the normal matrix N = n² I − MᵀM (M = Σ R_Ai) of the translation step
// over all station pairs; its eigenvector of the smallest eigenvalue is the least observed
// direction of X's translation, in X's parent frame.
Eigen::Matrix3d TranslationNormalMatrix(const std::vector<Pose>& A);

// Throws hecal::DegenerateError naming what cannot be observed and what data would fix it; for
// parallel axes the fix names the component a planar robot gives (--fix, planar.h).
// translation_fixed: one component of X's translation is given (planar.h), so parallel axes are
// not an error (the other checks remain).
void CheckObservability(const Problem& problem, bool translation_fixed = false);

// The noise-aware check above, for a robot rotation noise σ (radians per axis, given or
// estimated; σ = 0 disables it). Throws DegenerateError when a direction of X's translation is
// observed only by noise; returns a warning (empty when none) when it is weakly observed.
// translation_fixed: the least observed direction is given (planar.h); the next one is tested.
std::string CheckObservabilityUnderNoise(const Problem& problem, double robot_rotation_sigma,
                                         bool translation_fixed = false);

}  // namespace hecal::handeye
