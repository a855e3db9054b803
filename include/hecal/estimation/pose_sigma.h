// Noise model of one measured pose (docs/conventions.md): the measurement is T̃ = T · Exp(δ) (right
// perturbation), δ = (ω, v) ~ N(0, diag(σ_r² I₃, σ_t² I₃)) — independent, isotropic rotation and
// translation noise of the given per-component standard deviations. This is the model of
// `--robot-sigma MM,DEG` / `--camera-sigma MM,DEG` and of the thesis simulations
// (docs/thesis-study.md).
#pragma once

#include "hecal/geometry/types.h"

namespace hecal::estimation {

// Per-component standard deviations of a pose measurement (right perturbation,
// docs/conventions.md).
struct PoseSigma {
  double rotation = 0.0;     // radians, per axis
  double translation = 0.0;  // metres, per axis
};

// diag(σ_r², σ_r², σ_r², σ_t², σ_t², σ_t²), (ω, v) order.
inline Matrix6d PoseCovariance(const PoseSigma& sigma) {
  Vector6d diagonal;
  const double r2 = sigma.rotation * sigma.rotation;
  const double t2 = sigma.translation * sigma.translation;
  diagonal << r2, r2, r2, t2, t2, t2;
  return diagonal.asDiagonal();
}

}  // namespace hecal::estimation
