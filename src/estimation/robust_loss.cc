#include "hecal/estimation/robust_loss.h"

#include <cmath>

namespace hecal::estimation {

std::optional<RobustLoss> ParseRobustLoss(std::string_view name) {
  if (name == "none") return RobustLoss::kNone;
  if (name == "huber") return RobustLoss::kHuber;
  if (name == "cauchy") return RobustLoss::kCauchy;
  return std::nullopt;
}

std::string_view RobustLossName(RobustLoss loss) {
  switch (loss) {
    case RobustLoss::kNone:
      return "none";
    case RobustLoss::kHuber:
      return "huber";
    case RobustLoss::kCauchy:
      return "cauchy";
  }
  return "none";
}

std::unique_ptr<ceres::LossFunction> MakeLoss(RobustLoss loss, double scale) {
  const double a = scale * std::sqrt(6.0);
  switch (loss) {
    case RobustLoss::kNone:
      return nullptr;
    case RobustLoss::kHuber:
      return std::make_unique<ceres::HuberLoss>(a);
    case RobustLoss::kCauchy:
      return std::make_unique<ceres::CauchyLoss>(a);
  }
  return nullptr;
}

double LossValue(const ceres::LossFunction* loss, double s) {
  if (loss == nullptr) return s;
  double rho[3];
  loss->Evaluate(s, rho);
  return rho[0];
}

double LossWeight(const ceres::LossFunction* loss, double s) {
  if (loss == nullptr) return 1.0;
  double rho[3];
  loss->Evaluate(s, rho);
  return rho[1];
}

}  // namespace hecal::estimation
