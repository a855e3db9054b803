// Degeneracy checks run before any solver (issue 3: "Degenerate input ... gives a clear error
// naming the unobservable part, exit 2 — never a silent number").
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
#pragma once

#include <vector>

#include "hecal/handeye/motion.h"
#include "hecal/handeye/problem.h"

namespace hecal::handeye {

inline constexpr double kMinRotation = 1e-3;   // rad: below this a motion is a translation
inline constexpr double kParallelAxes = 1e-3;  // rad: spread of axes below this is parallel

// Throws hecal::DegenerateError naming what cannot be observed and what data would fix it.
void CheckObservability(const Problem& problem);

}  // namespace hecal::handeye
