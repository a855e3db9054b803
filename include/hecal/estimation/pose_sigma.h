// Noise model of one measured pose (docs/conventions.md): the measurement is T̃ = T · Exp(δ) (right
// perturbation), δ = (ω, v) ~ N(0, diag(σ_r² I₃, σ_t² I₃)) — independent, isotropic rotation and
// translation noise of the given per-component standard deviations. This is the model of
// `--robot-sigma MM,DEG` / `--camera-sigma MM,DEG` and of the thesis simulations
// (docs/thesis-study.md).
//
// A sigma is valid when finite, non-negative and at most kMaxSigmaRotation (180°) and
// kMaxSigmaTranslation (1 m) per axis: larger values are no device's noise, and a sigma is a
// standard deviation, so 0 is allowed (that side exact) but not below.
#pragma once

#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>

#include "hecal/core/options_check.h"
#include "hecal/geometry/types.h"

namespace hecal::estimation {

// Per-component standard deviations of a pose measurement (right perturbation,
// docs/conventions.md).
struct PoseSigma {
  double rotation = 0.0;     // radians, per axis
  double translation = 0.0;  // metres, per axis
};

// diag(σ_r², σ_r², σ_r², σ_t², σ_t², σ_t²), (ω, v) order.
inline constexpr double kMaxSigmaRotation = std::numbers::pi;  // radians (180°)
inline constexpr double kMaxSigmaTranslation = 1.0;            // metres

// For IsValid: false with `why` naming `field` when `sigma` is given and outside the range above.
inline bool SigmaIsValid(const std::optional<PoseSigma>& sigma, std::string_view field,
                         std::string* why) {
  if (!sigma) return true;
  // 1e-12 relative: 180 degrees converted to radians may round one ulp above π.
  const bool ok = sigma->rotation >= 0.0 && sigma->rotation <= kMaxSigmaRotation * (1 + 1e-12) &&
                  sigma->translation >= 0.0 && sigma->translation <= kMaxSigmaTranslation;
  if (ok) return true;
  char got[96];
  std::snprintf(got, sizeof(got), "%g mm / %g deg", sigma->translation * 1e3,
                sigma->rotation * 180.0 / std::numbers::pi);
  return Invalid(
      why, field,
      std::string("noise levels must be 0 to 1000 mm and 0 to 180 deg per axis, got ") + got,
      "give the standard deviation of one axis, e.g. 0.5 mm and 0.1 deg");
}

inline Matrix6d PoseCovariance(const PoseSigma& sigma) {
  Vector6d diagonal;
  const double r2 = sigma.rotation * sigma.rotation;
  const double t2 = sigma.translation * sigma.translation;
  diagonal << r2, r2, r2, t2, t2, t2;
  return diagonal.asDiagonal();
}

}  // namespace hecal::estimation
