// The model check of the target-free covariance (docs/global.md, "The model check"): the
// covariance of the polish with the robot's pose error marginalised
// (estimation/epipolar_robot_noise.h) is right when its noise model is — rays with independent
// isotropic noise, robot poses with independent isotropic errors. Matches that are wrong but
// consistent with one epipolar geometry, keypoints displaced alike in two images, or a robot
// whose errors are correlated between poses break it, and the covariance then understates the
// error with nothing in the result to show it (rwhe-kuka2 with SIFT matches: the rotation
// 5 σ from `ml`'s).
//
// Estimator: the delete-group jackknife over stations of estimation/model_check.h (Efron and
// Stein 1981; Shao and Tu 1995, §5.2), whose comparison and inflation rule it reuses
// (estimation::CompareWithJackknife: flag an axis of X when the jackknife σ exceeds the model's
// by more than kModelCheckFlagLevel sampling errors, inflate by the ratio shrunk towards 1). The
// stations are dealt into G = min(n, 20) groups (estimation::JackknifeGroups); without group g,
// every motion that uses one of its stations is dropped and X is polished again from X̂ with
// the noise levels held (PolishWithRobotNoise), giving d_g = Log(X̂⁻¹ X_(−g)) (right
// perturbation (ω, v)). Stations are the independent units of the noise model (a robot pose's
// error is shared by every match of the motions that use it).
// The spread the noise model itself predicts for this jackknife, E_jk, is computed in the
// problem linearised at X̂ (estimation::ExpectedEpipolarJackknife): groups overlap (a motion is
// dropped with either of its stations) and so the raw jackknife is not Var(X̂) — on disjoint
// motions each motion is dropped twice and the raw spread is about twice the model's variance.
// σ_check = σ_model · √(C_jk / E_jk) per axis; its sampling error is the larger of the Gaussian
// one under the model (same function) and the spread of the groups' terms; flagging and
// inflation as CompareWithJackknife (kModelCheckFlagLevel = 2, ratio shrunk towards 1).
// Not checked, by construction: an error every station shares alike (e.g. wrong intrinsics,
// a wrong board scale), which moves every X_(−g) with X̂.
// Not possible with fewer than kModelCheckMinStations stations, or when a polish without a group
// fails or is not finite (the rest does not determine X): the reason is returned and the
// covariance is left as it is.
#pragma once

#include <string>

#include "hecal/estimation/epipolar_robot_noise.h"
#include "hecal/estimation/model_check.h"
#include "hecal/global/epipolar_problem.h"

namespace hecal::report {

struct GlobalCovarianceCheck {
  estimation::ModelCheck check;            // X's axes in 0–5; Z's (6–11) unused
  Matrix6d covariance = Matrix6d::Zero();  // to report: inflated when check.used, else the model's
  std::string warning;                     // empty unless inflated or not possible
};

// The check on the polish's inliers at its X, covariance and noise levels.
GlobalCovarianceCheck CheckGlobalCovariance(const global::EpipolarProblem& inliers,
                                            const estimation::RobotNoisePolish& polish);

}  // namespace hecal::report
