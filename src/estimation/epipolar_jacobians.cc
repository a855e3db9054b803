// The target-free problem's residuals and their Jacobians (epipolar_jacobians.h), by ceres'
// automatic differentiation of epipolar_residual.h.
#include "epipolar_jacobians.h"

#include <ceres/autodiff_cost_function.h>

#include <string>

#include "epipolar_residual.h"
#include "hecal/core/error.h"

namespace hecal::estimation::detail {
namespace {

// r as a function of δ (X) and the two stations' η.
struct StationPairCost {
  StationPairCost(const Pose& X0, const Pose& B, const global::BearingPair& pair)
      : X0_(X0), B_(B), pair_(pair) {}

  template <typename T>
  bool operator()(const T* delta, const T* eta_first, const T* eta_second, T* residual) const {
    residual[0] = SampsonResidual<T>(X0_, B_, pair_, delta, eta_first, eta_second);
    return true;
  }

  Pose X0_, B_;
  global::BearingPair pair_;
};

int CheckedPairCount(const global::EpipolarProblem& problem) {
  const int n = global::PairCount(problem);
  if (n < 7) {
    throw DegenerateError(
        "the hand–eye transform (6 unknowns) from " + std::to_string(n) + " bearing pairs",
        "give at least 7 point matches");
  }
  return n;
}

}  // namespace

std::map<int, int> EpipolarStationIndex(const global::EpipolarProblem& problem) {
  std::map<int, int> index;
  for (const global::EpipolarMotion& motion : problem.motions) {
    for (int station : {motion.first_station, motion.second_station}) {
      index.emplace(station, int(index.size()));
    }
  }
  return index;
}

EpipolarJacobians DifferentiateEpipolar(const global::EpipolarProblem& problem, const Pose& X) {
  const std::map<int, int> station = EpipolarStationIndex(problem);
  const int p = 6 * int(station.size());
  const int n = CheckedPairCount(problem);
  EpipolarJacobians out;
  out.G = Eigen::MatrixXd::Zero(n, p);
  out.J.resize(n, 6);
  out.r.resize(n);
  Eigen::MatrixXd& G = out.G;
  Eigen::MatrixXd& J = out.J;
  Eigen::VectorXd& r = out.r;
  const double zero[6] = {0, 0, 0, 0, 0, 0};
  const double* parameters[3] = {zero, zero, zero};
  int row = 0;
  for (const global::EpipolarMotion& motion : problem.motions) {
    const int f = 6 * station.at(motion.first_station);
    const int s = 6 * station.at(motion.second_station);
    for (const global::BearingPair& pair : motion.pairs) {
      ceres::AutoDiffCostFunction<StationPairCost, 1, 6, 6, 6> cost(
          new StationPairCost(X, motion.hand, pair));
      double d_delta[6], d_first[6], d_second[6];
      double* jacobians[3] = {d_delta, d_first, d_second};
      cost.Evaluate(parameters, &r[row], jacobians);
      for (int k = 0; k < 6; ++k) {
        J(row, k) = d_delta[k];
        G(row, f + k) += d_first[k];
        G(row, s + k) += d_second[k];
      }
      ++row;
    }
  }
  return out;
}

}  // namespace hecal::estimation::detail
