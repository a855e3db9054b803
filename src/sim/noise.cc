#include "hecal/sim/noise.h"

#include "hecal/geometry/se3.h"

namespace hecal::sim {

std::optional<NoiseModel::Kind> ParseNoiseKind(std::string_view text) {
  if (text == "gaussian") return NoiseModel::Kind::kGaussian;
  if (text == "uniform") return NoiseModel::Kind::kUniform;
  if (text == "systematic") return NoiseModel::Kind::kSystematic;
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
  }
  return "gaussian";
}

Vector6d SamplePerturbation(const NoiseModel& model, std::mt19937_64& rng) {
  Vector6d delta;
  const double sigma[2] = {model.rotation_sigma, model.translation_sigma};
  for (int k = 0; k < 6; ++k) {
    const double s = sigma[k / 3];
    switch (model.kind) {
      case NoiseModel::Kind::kGaussian:
        delta(k) = s * std::normal_distribution<double>()(rng);
        break;
      case NoiseModel::Kind::kUniform:
        delta(k) = s * std::uniform_real_distribution<double>(-1.0, 1.0)(rng);
        break;
      case NoiseModel::Kind::kSystematic:
        delta(k) = s;
        break;
    }
  }
  return delta;
}

Pose AddNoise(const Pose& T, const NoiseModel& model, std::mt19937_64& rng) {
  if (model.IsZero()) return T;
  return T * se3::Exp(SamplePerturbation(model, rng));
}

}  // namespace hecal::sim
