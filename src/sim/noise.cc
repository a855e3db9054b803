#include "hecal/sim/noise.h"

#include <cmath>

#include "hecal/core/random_draws.h"
#include "hecal/geometry/se3.h"
#include "hecal/geometry/so3.h"

namespace hecal::sim {

std::optional<NoiseModel::Kind> ParseNoiseKind(std::string_view text) {
  if (text == "gaussian") return NoiseModel::Kind::kGaussian;
  if (text == "uniform") return NoiseModel::Kind::kUniform;
  if (text == "systematic") return NoiseModel::Kind::kSystematic;
  if (text == "student-t3") return NoiseModel::Kind::kStudentT3;
  if (text == "pnp") return NoiseModel::Kind::kPnp;
  return std::nullopt;
}

std::string_view NoiseKindName(NoiseModel::Kind kind) {
  switch (kind) {
    case NoiseModel::Kind::kGaussian:
      return "gaussian";
    case NoiseModel::Kind::kUniform:
      return "uniform";
    case NoiseModel::Kind::kSystematic:
      return "systematic";
    case NoiseModel::Kind::kStudentT3:
      return "student-t3";
    case NoiseModel::Kind::kPnp:
      return "pnp";
  }
  return "gaussian";
}

Vector6d SamplePerturbation(const NoiseModel& model, std::mt19937_64& rng) {
  Vector6d delta;
  const double sigma[2] = {model.rotation_sigma, model.translation_sigma};
  // kPnp: tilt x, y, spin z; lateral x, y, depth z (noise.h), in units of σ.
  constexpr double kPnpShape[6] = {2.0, 2.0, 0.1, 0.5, 0.5, 5.0};
  for (int k = 0; k < 6; ++k) {
    const double s = sigma[k / 3];
    switch (model.kind) {
      case NoiseModel::Kind::kGaussian:
        delta(k) = s * hecal::NormalDistribution()(rng);
        break;
      case NoiseModel::Kind::kUniform:
        delta(k) = s * hecal::UniformRealDistribution(-1.0, 1.0)(rng);
        break;
      case NoiseModel::Kind::kSystematic:
        delta(k) = s;
        break;
      case NoiseModel::Kind::kStudentT3:
        delta(k) = s * std::student_t_distribution<double>(3.0)(rng) / std::sqrt(3.0);
        break;
      case NoiseModel::Kind::kPnp:
        delta(k) = s * kPnpShape[k] * hecal::NormalDistribution()(rng);
        break;
    }
  }
  return delta;
}

Pose AddNoise(const Pose& T, const NoiseModel& model, std::mt19937_64& rng) {
  if (model.IsZero()) return T;
  const Vector6d delta = SamplePerturbation(model, rng);
  if (model.kind != NoiseModel::Kind::kPnp) return T * se3::Exp(delta);
  Pose noisy = T;
  noisy.linear() = so3::Exp(delta.head<3>()) * T.linear();
  noisy.translation() = T.translation() + delta.tail<3>();
  return noisy;
}

}  // namespace hecal::sim
