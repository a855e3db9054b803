// Method `strobl`: Strobl & Hirzinger's optimal hand–eye calibration (K. H. Strobl,
// G. Hirzinger, "Optimal Hand-Eye Calibration", IEEE/RSJ IROS 2006;
// docs/handeye-methods.md#strobl-and-hirzinger), on the absolute-pose loops Z = A_i X B_i with
// their SE(3) metric and automatic weighting.
//
// What hecal implements, precisely:
//  - per station the rotation error rot_i = angle of Z⁻¹ A_i X B_i and the translation error
//    tra_i² = (|t_E|² + |t_D|²)/2, the discrepancy seen from the target end and from the base end
//    of the loop (strobl_cost.h);
//  - the cost Υ(X, Z) = Σ_i rot_i² / σ_rot² + tra_i² / σ_tra², minimised jointly over X and Z on
//    SE(3) × SE(3) (Ceres, analytic Jacobians);
//  - automatic weighting: σ_rot² = mean_i rot_i² and σ_tra² = mean_i tra_i² at the current
//    estimate (the maximum-likelihood variances of the isotropic error model Strobl & Hirzinger
//    assume), re-estimated after every minimisation until the ratio σ_tra/σ_rot changes by less
//    than 1e-6 (at most max_iterations minimisations);
//  - initialisation: every start (normally all closed-form solutions) is refined with the
//    initial weights (the smallest residual RMS over the starts) and the lowest Υ is kept, as
//    for ml (multi-start rule in ml.h).
// Unlike ml, the metric ignores how robot and camera noise propagate through the lever arms,
// so it is not at the statistical bound; it is the thesis' named refinement and a noise-model-
// free alternative. The ratio σ_tra/σ_rot is kept within [1e-6, 1e6]·L (L = LengthScale) so that
// noise-free data (all errors → 0) stay well posed.
#pragma once

#include <string>
#include <vector>

#include "hecal/handeye/problem.h"

namespace hecal::estimation {

struct StroblOptions {
  int max_iterations = 20;  // weight re-estimations, at least 1

  // core/options_check.h: false naming StroblOptions.max_iterations below 1.
  bool IsValid(std::string* why) const;
};

struct StroblResult {
  Pose X = Pose::Identity();
  Pose Z = Pose::Identity();
  double sigma_rotation = 0.0;     // rad: RMS rotation error at the optimum (the weight used)
  double sigma_translation = 0.0;  // m: RMS translation error at the optimum
  double cost = 0.0;               // Υ at the optimum with those weights
  int iterations = 0;              // weight re-estimations
  int starts_refined = 0;
};

// Throws hecal::DegenerateError for fewer than 3 stations, std::invalid_argument when `starts` is
// empty.
StroblResult RefineStrobl(const handeye::Problem& problem,
                          const std::vector<handeye::Solution>& starts,
                          const StroblOptions& options = {});

}  // namespace hecal::estimation
