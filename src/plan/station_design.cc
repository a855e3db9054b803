// Choosing stations by the predicted covariance of X (station_design.h).
#include "hecal/plan/station_design.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <limits>

#include "hecal/estimation/bound.h"

namespace hecal::plan {
namespace {

constexpr double kRidge = 1e-9;
constexpr int kExchangePasses = 3;

// M_X = I_XX − I_XZ I_ZZ⁻¹ I_ZX with the ridge.
Eigen::Matrix<double, 6, 6> XInformation(const Matrix12d& information) {
  const double ridge = kRidge * std::max(information.diagonal().mean(), 1e-300);
  Matrix12d I = information;
  I.diagonal().array() += ridge;
  const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> zz(I.bottomRightCorner<6, 6>());
  return I.topLeftCorner<6, 6>() - I.topRightCorner<6, 6>() * zz.solve(I.bottomLeftCorner<6, 6>());
}

// The design's criterion: mean over scenes of log det M_X.
double Criterion(const std::vector<Matrix12d>& information) {
  double sum = 0.0;
  for (const Matrix12d& I : information) sum += XLogDet(I);
  return sum / static_cast<double>(information.size());
}

}  // namespace

std::vector<std::vector<Matrix12d>> CandidateInformation(
    const std::vector<ViewCandidate>& candidates, const std::vector<Scene>& scenes,
    const estimation::PoseSigma& robot_sigma, const estimation::PoseSigma& camera_sigma) {
  const Matrix6d robot = estimation::PoseCovariance(robot_sigma);
  const Matrix6d camera = estimation::PoseCovariance(camera_sigma);
  std::vector<std::vector<Matrix12d>> information(candidates.size());
  for (size_t c = 0; c < candidates.size(); ++c) {
    for (const Scene& scene : scenes) {
      const Pose A = scene.setup == handeye::Setup::kEyeInHand
                         ? candidates[c].T_base_gripper
                         : candidates[c].T_base_gripper.inverse();
      const Pose B = (A * scene.X).inverse() * scene.Z;
      information[c].push_back(
          estimation::StationInformation(scene.setup, A, B, scene.X, scene.Z, robot, camera));
    }
  }
  return information;
}

double XLogDet(const Matrix12d& information) {
  const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> ldlt(XInformation(information));
  double log_det = 0.0;
  for (int k = 0; k < 6; ++k)
    log_det += std::log(std::max(ldlt.vectorD()(k), std::numeric_limits<double>::min()));
  return log_det;
}

Eigen::Matrix<double, 6, 6> XCovariance(const Matrix12d& information) {
  return XInformation(information).inverse();
}

std::vector<int> ChooseStations(const std::vector<std::vector<Matrix12d>>& information,
                                const std::vector<Matrix12d>& base, int count, bool exchange) {
  const int candidates = static_cast<int>(information.size());
  std::vector<int> chosen;
  std::vector<bool> taken(information.size(), false);
  std::vector<Matrix12d> current = base;
  const auto with = [&](const std::vector<Matrix12d>& sum, int c, double sign) {
    std::vector<Matrix12d> out = sum;
    for (size_t k = 0; k < out.size(); ++k) out[k] += sign * information[c][k];
    return out;
  };
  for (int step = 0; step < count && step < candidates; ++step) {
    int best = -1;
    double best_value = -std::numeric_limits<double>::infinity();
    for (int c = 0; c < candidates; ++c) {
      if (taken[c]) continue;
      const double value = Criterion(with(current, c, 1.0));
      if (value > best_value) {
        best_value = value;
        best = c;
      }
    }
    taken[best] = true;
    chosen.push_back(best);
    current = with(current, best, 1.0);
  }
  for (int pass = 0; exchange && pass < kExchangePasses; ++pass) {
    bool improved = false;
    for (int& station : chosen) {
      const std::vector<Matrix12d> without = with(current, station, -1.0);
      double best_value = Criterion(current);
      int best = -1;
      for (int c = 0; c < candidates; ++c) {
        if (taken[c]) continue;
        const double value = Criterion(with(without, c, 1.0));
        if (value > best_value + 1e-9) {
          best_value = value;
          best = c;
        }
      }
      if (best >= 0) {
        taken[station] = false;
        taken[best] = true;
        station = best;
        current = with(without, best, 1.0);
        improved = true;
      }
    }
    if (!improved) break;
  }
  return chosen;
}

}  // namespace hecal::plan
