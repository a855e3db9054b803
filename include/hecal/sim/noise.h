// Measurement noise models for simulated poses (thesis SPEC.md A.4: Gaussian with σ = n mm and
// n° per component, uniform, and systematic errors).
//
// A noisy pose is T̃ = T · Exp(δ) (right perturbation, DESIGN.md §2), δ = (ω, v), with per
// component:
//   kGaussian    ω_k ~ N(0, σ_r²), v_k ~ N(0, σ_t²)
//   kUniform     ω_k ~ U(−σ_r, σ_r), v_k ~ U(−σ_t, σ_t)   ("±n": std is σ/√3)
//   kSystematic  ω_k = +σ_r, v_k = +σ_t for every pose (a constant, non-zero-mean error; the
//                same offset for the whole data set, like a mis-measured tool frame)
#pragma once

#include <optional>
#include <random>
#include <string_view>

#include "hecal/geometry/types.h"

namespace hecal::sim {

struct NoiseModel {
  enum class Kind { kGaussian, kUniform, kSystematic };
  Kind kind = Kind::kGaussian;
  double rotation_sigma = 0.0;     // radians
  double translation_sigma = 0.0;  // metres

  bool IsZero() const { return rotation_sigma == 0.0 && translation_sigma == 0.0; }
};

// "gaussian" | "uniform" | "systematic"
std::optional<NoiseModel::Kind> ParseNoiseKind(std::string_view text);
std::string_view NoiseKindName(NoiseModel::Kind kind);

// Draws δ for one pose (rotation first).
Vector6d SamplePerturbation(const NoiseModel& model, std::mt19937_64& rng);
// T · Exp(δ) with δ from SamplePerturbation.
Pose AddNoise(const Pose& T, const NoiseModel& model, std::mt19937_64& rng);

}  // namespace hecal::sim
