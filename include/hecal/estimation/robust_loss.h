// Optional robust losses for the refinements (ml, strobl): the per-station cost s = |W r|² (the
// squared whitened residual, E[s] = 6 for an inlier) becomes ρ(s) (Ceres' convention):
//   none     ρ(s) = s
//   huber    ρ(s) = s                 for s ≤ a²,   2a√s − a²  beyond   (Huber 1964)
//   cauchy   ρ(s) = a² · log(1 + s/a²)                                  (Cauchy / Lorentzian)
// with a = scale · √6: `scale` is in whitened units per component, so the default scale 3 starts
// down-weighting a station whose whitened RMS residual exceeds 3 (the outlier level of
// calibrate.h). A station's weight in the normal equations is ρ'(s) ∈ (0, 1].
#pragma once

#include <ceres/loss_function.h>

#include <memory>
#include <optional>
#include <string_view>

namespace hecal::estimation {

enum class RobustLoss { kNone, kHuber, kCauchy };

// "none" | "huber" | "cauchy"; nullopt otherwise.
std::optional<RobustLoss> ParseRobustLoss(std::string_view name);
std::string_view RobustLossName(RobustLoss loss);

// The Ceres loss for `loss` at the given whitened scale; nullptr for kNone (plain least squares).
std::unique_ptr<ceres::LossFunction> MakeLoss(RobustLoss loss, double scale);

// ρ(s) and ρ'(s) of `loss` (nullptr: ρ(s) = s).
double LossValue(const ceres::LossFunction* loss, double s);
double LossWeight(const ceres::LossFunction* loss, double s);

}  // namespace hecal::estimation
