// Choosing stations by the predicted covariance of X (docs/plan.md#how-the-poses-are-chosen).
//
// Criterion: D-optimal for X. Each station adds its Fisher information J_iᵀ Σ_i⁻¹ J_i (12 × 12
// over (δX, δZ), estimation/bound.h) at the nominal scene; Z is a nuisance, so what X gets is the
// Schur complement M_X = I_XX − I_XZ I_ZZ⁻¹ I_ZX, whose inverse is the first-order covariance of
// X. The design maximises log det M_X — the volume of X's confidence ellipsoid, which unlike the
// trace does not depend on how radians are weighed against metres. Robust to the nominal's error:
// the criterion is the mean of log det M_X over the nominal scene and its perturbed copies
// (a Bayesian D-optimal design over the nominal's uncertainty; Chaloner & Verdinelli, Statistical
// Science 10(3), 1995), whose candidates also see the target (view_candidates.h).
// Search: greedy (each step adds the candidate that raises the criterion most), then Fedorov
// exchange passes (swap a chosen station for a candidate while that raises it) until none does
// or 3 passes. The first stations' information is singular; a ridge of 1e-9 × its mean diagonal
// keeps the log-determinant finite until enough stations are in.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "hecal/estimation/pose_sigma.h"
#include "hecal/plan/view_candidates.h"

namespace hecal::plan {

using Matrix12d = Eigen::Matrix<double, 12, 12>;

// information[c][k]: candidate c's information at scene k.
std::vector<std::vector<Matrix12d>> CandidateInformation(
    const std::vector<ViewCandidate>& candidates, const std::vector<Scene>& scenes,
    const estimation::PoseSigma& robot_sigma, const estimation::PoseSigma& camera_sigma);

// log det M_X of an information matrix (with the ridge; −∞ never returned).
double XLogDet(const Matrix12d& information);

// The first-order covariance of X (6 × 6, right perturbation, (ω, v)): M_X⁻¹.
Eigen::Matrix<double, 6, 6> XCovariance(const Matrix12d& information);

// `count` candidate indices chosen as above, on top of `base` (one information per scene: the
// stations already taken; zeros for a new plan), in the order the greedy step took them;
// exchange false: the greedy steps only.
std::vector<int> ChooseStations(const std::vector<std::vector<Matrix12d>>& information,
                                const std::vector<Matrix12d>& base, int count,
                                bool exchange = true);

}  // namespace hecal::plan
