// Measurement noise models for simulated poses (thesis docs/thesis-study.md: Gaussian with σ = n mm
// and n° per component, uniform, and systematic errors).
//
// A noisy pose is T̃ = T · Exp(δ) (right perturbation, docs/conventions.md), δ = (ω, v), with per
// component:
//   kGaussian    ω_k ~ N(0, σ_r²), v_k ~ N(0, σ_t²)
//   kUniform     ω_k ~ U(−σ_r, σ_r), v_k ~ U(−σ_t, σ_t)   ("±n": std is σ/√3)
//   kSystematic  ω_k = +σ_r, v_k = +σ_t for every pose (a constant, non-zero-mean error; the
//                same offset for the whole data set, like a mis-measured tool frame)
//   kStudentT3   ω_k = σ_r·τ/√3, v_k = σ_t·τ/√3 with τ ~ Student-t with 3 degrees of freedom
//                (heavy-tailed; per-component standard deviation σ, infinite kurtosis)
//   kPnp         the shape of a camera pose from PnP on a planar target about 1 m away
//                (anisotropic, in the CAMERA frame, T = T_camera_target): the target tilts about
//                the camera's x and y axes by N(0, (2σ_r)²) and spins about the optical axis by
//                N(0, (0.1σ_r)²), its origin moves by N(0, (0.5σ_t)²) sideways and N(0, (5σ_t)²)
//                in depth: R̃ = Exp(ω_cam)·R, t̃ = t + v_cam. At σ = 1 mm / 1°: tilt 2°, spin
//                0.1°, depth 5 mm, lateral 0.5 mm. Only meaningful for camera poses.
#pragma once

#include <optional>
#include <random>
#include <string_view>

#include "hecal/geometry/types.h"

namespace hecal::sim {

struct NoiseModel {
  enum class Kind { kGaussian, kUniform, kSystematic, kStudentT3, kPnp };
  Kind kind = Kind::kGaussian;
  double rotation_sigma = 0.0;     // radians
  double translation_sigma = 0.0;  // metres

  bool IsZero() const { return rotation_sigma == 0.0 && translation_sigma == 0.0; }
};

// "gaussian" | "uniform" | "systematic" | "student-t3" | "pnp"
std::optional<NoiseModel::Kind> ParseNoiseKind(std::string_view text);
std::string_view NoiseKindName(NoiseModel::Kind kind);

// Draws δ for one pose (rotation first); for kPnp the perturbation in the camera frame
// (ω_cam, v_cam).
Vector6d SamplePerturbation(const NoiseModel& model, std::mt19937_64& rng);
// T · Exp(δ) with δ from SamplePerturbation; for kPnp (Exp(ω_cam)·R, t + v_cam).
Pose AddNoise(const Pose& T, const NoiseModel& model, std::mt19937_64& rng);

}  // namespace hecal::sim
