// Monte Carlo covariance of the image-level estimate (reprojection_refinement.h), for
// `hecal calibrate --images --covariance montecarlo`: the reference for the linear covariance
// of the reprojection problem on real images.
//
// Sample k (uncertainty/monte_carlo.h: z_k = StandardNormalSample(seed, k, 6n + 2m), n images,
// m points in all) perturbs
//  - every robot pose on the right, T_base_gripper_i · Exp(D z_k,i), D = diag(σ_r I₃, σ_t I₃)
//    with the robot sigma used by the estimate, and
//  - every detected pixel by σ_px z_k,j (the pixel sigma used),
// then re-runs RefineReprojection from the estimate's (X, Z) with both sigmas fixed at those
// values (and the intrinsics refined again when they were). The covariance of the (X, Z) of
// the samples, with the standard error of each σ, is the result. The UT is not offered here:
// its 2(6n + 2m) + 1 points would be thousands of refinements.
#pragma once

#include <vector>

#include "hecal/estimation/covariance_method.h"
#include "hecal/estimation/reprojection_refinement.h"

namespace hecal::estimation {

// `estimate`: RefineReprojection(T_base_gripper, images, ..., options)'s result. Uses
// covariance.samples, .seed and .threads. Throws DegenerateError when fewer than 2 samples
// succeed.
CalibrationCovariance ImageMonteCarloCovariance(const std::vector<Pose>& T_base_gripper,
                                                const std::vector<ImagePoints>& images,
                                                const ReprojectionResult& estimate,
                                                const ReprojectionOptions& options,
                                                const CovarianceOptions& covariance);

}  // namespace hecal::estimation
