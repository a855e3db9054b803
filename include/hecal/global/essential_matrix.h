// The essential matrix of one camera motion from bearing pairs (Hartley & Zisserman, "Multiple
// View Geometry", 2nd ed., §9.6 and §11.2), used by the pre-filter (outlier_removal.h) and the
// local start (local_start.h) of the global method.
//
// Notation as in epipolar_problem.h: a pair (v, u) has unit rays v in the first and u in the
// second camera frame; the camera motion A has R_A (second frame → first) and t_A (second centre
// in the first frame). The epipolar constraint v · (t_A × R_A u) = 0 is vᵀ E u = 0 with
//   E = [t_A]× R_A.
// EightPoint: the least-squares E (unit Frobenius norm, not projected onto the essential
// manifold) from ≥ 8 pairs, the right singular vector of the smallest singular value of the
// N × 9 system.
// SampsonError: |vᵀ E u| / sqrt(|P_v E u|² + |P_u Eᵀ v|²), P_x = I − x xᵀ, the first-order
// angle (radians of ray) by which the rays must turn to satisfy the constraint.
// RotationFromEssential: of the two rotations U W Vᵀ, U Wᵀ Vᵀ of E = U diag(1, 1, 0) Vᵀ and the two
// signs of t_A = ±U e₃ (§9.6.2), the one that puts most pairs' triangulated points in front of
// both cameras (λ v = t_A + μ R_A u with λ, μ > 0). nullopt when fewer than 8 pairs.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "hecal/global/epipolar_problem.h"

namespace hecal::global {

// Precondition: sample has at least 8 indices into pairs.
Eigen::Matrix3d EightPoint(const std::vector<BearingPair>& pairs, const std::vector<int>& sample);

double SampsonError(const Eigen::Matrix3d& E, const BearingPair& pair);

// R_A of the motion from every pair (eight-point on all, then the cheirality test).
std::optional<Eigen::Matrix3d> RotationFromEssential(const std::vector<BearingPair>& pairs);

}  // namespace hecal::global
