// Optional robust losses for the refinements (ml, strobl): the per-station cost s = |W r|² (the
// squared whitened residual, E[s] = 6 for an inlier) becomes ρ(s) (Ceres' convention):
//   none     ρ(s) = s
//   huber    ρ(s) = s                 for s ≤ a²,   2a√s − a²  beyond   (Huber 1964)
//   cauchy   ρ(s) = a² · log(1 + s/a²)                                  (Cauchy / Lorentzian)
// with a = scale · √6: `scale` is in whitened units per component. The default,
// kOutlierLevelScale = √(20.06/6) = 1.829, puts a² at the χ² quantile of the two-sided 3σ level
// for 6 degrees of freedom, the level at which calibrate.h flags a station: a station is
// down-weighted exactly when it would be flagged. (A scale of 3, a² = 54, left flagged stations
// with 20 < s < 54 at full weight.) A station's weight in the normal equations is ρ'(s) ∈ (0, 1].
#pragma once

#include <ceres/loss_function.h>

#include <memory>
#include <optional>
#include <string_view>

namespace hecal::estimation {

enum class RobustLoss { kNone, kHuber, kCauchy };

// √(χ²₆(0.9973) / 6): the whitened RMS per component at the 3σ outlier level.
inline constexpr double kOutlierLevelScale = 1.8285734952871506;

// "none" | "huber" | "cauchy"; nullopt otherwise.
std::optional<RobustLoss> ParseRobustLoss(std::string_view name);
std::string_view RobustLossName(RobustLoss loss);

// The Ceres loss for `loss` at the given whitened scale; nullptr for kNone (plain least squares).
std::unique_ptr<ceres::LossFunction> MakeLoss(RobustLoss loss, double scale);

// ρ(s) and ρ'(s) of `loss` (nullptr: ρ(s) = s).
double LossValue(const ceres::LossFunction* loss, double s);
double LossWeight(const ceres::LossFunction* loss, double s);

}  // namespace hecal::estimation
