// The model check of the target-free covariance: see global_calibration_check.h.
#include "hecal/report/global_calibration_check.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <iomanip>
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "hecal/geometry/se3.h"

namespace hecal::report {
namespace {

using Matrix12d = Eigen::Matrix<double, 12, 12>;

constexpr const char* kAxes[6] = {"rx", "ry", "rz", "tx", "ty", "tz"};
const std::string kUnchecked = "the covariance trusts the noise model unchecked: ";

// The model covariance of X as the 12-axis (X, Z) matrix of estimation::ModelCheck; Z's block
// is the identity (target-free: there is no Z; its deviations are zero and never flagged).
Matrix12d AsXZ(const Matrix6d& covariance) {
  Matrix12d out = Matrix12d::Identity();
  out.topLeftCorner<6, 6>() = covariance;
  return out;
}

}  // namespace

GlobalCovarianceCheck CheckGlobalCovariance(const global::EpipolarProblem& inliers,
                                            const estimation::RobotNoisePolish& polish) {
  GlobalCovarianceCheck out;
  out.covariance = polish.polish.covariance;
  std::map<int, size_t> index;  // station → its place among the stations used
  for (const global::EpipolarMotion& motion : inliers.motions) {
    if (motion.pairs.empty()) continue;
    for (const int station : {motion.first_station, motion.second_station}) {
      index.emplace(station, index.size());
    }
  }
  if (index.size() < estimation::kModelCheckMinStations) {
    out.check.reason = std::to_string(index.size()) + " stations, at least " +
                       std::to_string(estimation::kModelCheckMinStations) + " needed";
    out.warning = kUnchecked + out.check.reason;
    return out;
  }
  const std::vector<std::vector<bool>> groups = estimation::JackknifeGroups(index.size());
  std::vector<std::vector<bool>> kept_motions;  // per group, per motion of `inliers`
  std::vector<Vector6d> deviations;             // d_g
  try {
    for (const std::vector<bool>& kept : groups) {
      std::vector<bool> motions;
      global::EpipolarProblem rest = inliers;
      rest.motions.clear();
      for (const global::EpipolarMotion& motion : inliers.motions) {
        motions.push_back(!motion.pairs.empty() && kept[index.at(motion.first_station)] &&
                          kept[index.at(motion.second_station)]);
        if (motions.back()) rest.motions.push_back(motion);
      }
      if (global::PairCount(rest) < 7) throw std::runtime_error("fewer than 7 matches left");
      const estimation::EpipolarPolish solved =
          estimation::PolishWithRobotNoise(rest, polish.polish.X, polish.noise);
      const Vector6d d = se3::Log(polish.polish.X.inverse() * solved.X);
      if (!d.allFinite() || !solved.covariance.allFinite()) {
        throw std::runtime_error("the polish did not converge");
      }
      deviations.push_back(d);
      kept_motions.push_back(std::move(motions));
    }
  } catch (const std::exception& e) {
    out.check.reason = std::string("a polish without one group of stations failed: ") + e.what();
    out.warning = kUnchecked + out.check.reason;
    return out;
  }
  const estimation::EpipolarJackknife expected =
      estimation::ExpectedEpipolarJackknife(inliers, polish.polish.X, polish.noise, kept_motions);

  // The comparison and rule of estimation::CompareWithJackknife, with the model's own Gaussian
  // sampling error of the jackknife (EpipolarJackknife::relative_error) in place of √(2/(G − 1)).
  estimation::ModelCheck& check = out.check;
  check.possible = true;
  const int G = int(deviations.size());
  check.groups = G;
  check.model_covariance = AsXZ(polish.polish.covariance);
  Vector6d mean = Vector6d::Zero();
  for (const Vector6d& d : deviations) mean += d / G;
  for (int k = 0; k < 6; ++k) {
    double sum = 0.0, sum_sq = 0.0;
    for (const Vector6d& d : deviations) {
      const double t = (d(k) - mean(k)) * (d(k) - mean(k));
      sum += t;
      sum_sq += t * t;
    }
    const double variance = (G - 1.0) / G * sum;
    const double term_mean = sum / G;
    const double term_variance = std::max(0.0, (sum_sq - G * term_mean * term_mean) / (G - 1.0));
    const double spread_error = sum > 0.0 ? std::sqrt(G * term_variance) / sum : 0.0;
    const double e = expected.covariance(k, k);
    check.sigma_model(k) = std::sqrt(std::max(0.0, polish.polish.covariance(k, k)));
    check.sigma_check(k) = e > 0.0 ? check.sigma_model(k) * std::sqrt(variance / e) : 0.0;
    check.relative_error(k) = 0.5 * std::max(expected.relative_error(k), spread_error);
    check.flagged[std::size_t(k)] =
        check.sigma_check(k) >
        check.sigma_model(k) * (1.0 + estimation::kModelCheckFlagLevel * check.relative_error(k));
    check.used = check.used || check.flagged[std::size_t(k)];
  }
  if (!check.used) return out;
  out.covariance = estimation::ReportedCovariance(out.check).topLeftCorner<6, 6>();
  const auto ratio = out.check.Ratio();
  const auto inflation = out.check.Inflation();
  std::ostringstream text;
  text << std::setprecision(2)
       << "the matches spread more than the noise model says (jackknife over the stations): "
          "σ of X inflated on ";
  bool first = true;
  for (int k = 0; k < 6; ++k) {
    if (!out.check.flagged[size_t(k)]) continue;
    text << (first ? "" : ", ") << kAxes[k] << " (spread " << ratio(k) << "x the model's, σ ×"
         << inflation(k) << ")";
    first = false;
  }
  text << " (axes of X's own frame); likely causes: matches wrong but consistent with one motion, "
          "errors every match of an image shares, or robot errors correlated between poses";
  out.warning = text.str();
  return out;
}

}  // namespace hecal::report
