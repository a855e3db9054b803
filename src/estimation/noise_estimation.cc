#include "hecal/estimation/noise_estimation.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "fixed_size_kernels.h"
#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/geometry/dense_decompositions.h"
#include "hecal/uncertainty/consistency.h"

namespace hecal::estimation {
namespace {

using Matrix12d = Eigen::Matrix<double, 12, 12>;
using Vector12d = Eigen::Matrix<double, 12, 1>;

constexpr int kMaxGroups = 5;
constexpr int kMaxJointGroups = 2;        // the posterior mean's joint grid (header)
constexpr double kAbsoluteFloor = 1e-30;  // variance floor (σ = 1e-15)
constexpr double kRelativeFloor = 1e-6;   // variance ratio rotation·L² : translation, both ways
constexpr double kMaxDecrease = 0.1;      // per step, towards a boundary optimum
constexpr double kTolerance = 1e-6;       // relative change of the variances
constexpr int kMaxVarianceIterations = 200;
constexpr int kMaxExclusionRounds = 10;
constexpr int kMaxHalvings = 30;
// Posterior mean: points per estimated group of the coarse and the fine grid, the coarse grid's
// span relative to the group's energy bound, and the largest problem it is computed for.
constexpr int kCoarseGridPoints = 16;
constexpr int kFineGridPoints = 24;
constexpr double kPosteriorGridLow = 1e-6;
constexpr double kPosteriorGridHigh = 4.0;
constexpr size_t kPosteriorMaxStations = 100;
// A richer model is eligible only when each group it shares with the isotropic model rests on
// more effective degrees of freedom than this (header, "Richer noise models").
constexpr double kMinGroupDof = 2.0;

bool IsRotation(int k) {
  return k == kRobotRotation || k == kCameraRotation || k == kCameraTiltExcess;
}

// Weighted linear re-fit over the included stations: N⁻¹, δ = N⁻¹ Σ Jᵀ Σ⁻¹ r, and the
// restricted (REML) log-likelihood of the variances,
//   ℓ_R(θ) = −½ (Σ_i log det Σ_i + log det N + Σ_i r_iᵀ Σ_i⁻¹ r_i − bᵀ N⁻¹ b),  b = Σ Jᵀ Σ⁻¹ r.
// Variances θ that leave some station's Σ_i not positive definite (numerically) are outside the
// parameter space: `feasible` is false and ℓ_R = −∞, so a grid point or a trial step there loses.
struct Refit {
  bool feasible = true;
  std::vector<Matrix6d> inverse_covariance;
  Matrix12d N_inverse;
  Vector12d delta;
  double log_likelihood = 0.0;
};

// Σ⁻¹ = L⁻ᵀ L⁻¹ from Σ = L Lᵀ (fixed_size_kernels.h: a solve against the identity takes Eigen's
// blocked triangular-matrix path, the costliest part of a re-fit at 6×6).
Matrix6d InverseFromCholesky(const Matrix6d& lower) {
  const Matrix6d L_inverse = internal::LowerTriangularInverse(lower);
  return L_inverse.transpose().lazyProduct(L_inverse);
}

Refit LinearRefit(const std::vector<StationLinearization>& stations,
                  const std::vector<bool>& included, const NoiseVariances& theta) {
  Refit refit;
  Matrix12d N = Matrix12d::Zero();
  Vector12d b = Vector12d::Zero();
  double log_det_sigma = 0.0, quadratic = 0.0;
  refit.inverse_covariance.reserve(stations.size());
  for (size_t i = 0; i < stations.size(); ++i) {
    const Eigen::LLT<Matrix6d> llt(CombineComponents(stations[i].components, theta));
    if (llt.info() != Eigen::Success) {
      refit.feasible = false;
      refit.log_likelihood = -std::numeric_limits<double>::infinity();
      return refit;
    }
    refit.inverse_covariance.push_back(InverseFromCholesky(llt.matrixLLT()));
    if (!included[i]) continue;
    const Matrix6d& W = refit.inverse_covariance[i];
    const Eigen::Matrix<double, 12, 6> JtW = stations[i].jacobian.transpose().lazyProduct(W);
    N.noalias() += JtW.lazyProduct(stations[i].jacobian);
    b.noalias() += JtW * stations[i].residual;
    log_det_sigma += 2.0 * llt.matrixLLT().diagonal().array().log().sum();
    quadratic += stations[i].residual.dot(W * stations[i].residual);
  }
  const Eigen::LLT<Matrix12d> llt(N);
  if (llt.info() == Eigen::Success) {
    refit.N_inverse = llt.solve(Matrix12d::Identity());
    refit.delta = refit.N_inverse * b;
    const double log_det_N = 2.0 * llt.matrixLLT().diagonal().array().log().sum();
    refit.log_likelihood = -0.5 * (log_det_sigma + log_det_N + quadratic - b.dot(refit.delta));
  } else {
    refit.N_inverse = PseudoInverse12(N);
    refit.delta = refit.N_inverse * b;
    refit.log_likelihood = -std::numeric_limits<double>::infinity();
  }
  return refit;
}

// LinearRefit where the variances must be feasible: variances estimated from the data that
// still leave a station's covariance singular mean the data cannot support the noise model.
Refit FeasibleRefit(const std::vector<StationLinearization>& stations,
                    const std::vector<bool>& included, const NoiseVariances& theta) {
  Refit refit = LinearRefit(stations, included, theta);
  if (!refit.feasible) {
    throw DegenerateError(
        "the station noise model: the rotation and translation variances leave a station's "
        "6×6 pose-loop covariance singular (a variance the residuals do not determine)",
        "give the robot and camera sigmas (--robot-sigma, --camera-sigma) instead of "
        "estimating them, or check that the poses belong to this target and robot");
  }
  return refit;
}

// Applies the floors to the estimated groups.
void ApplyFloors(const NoiseSpec& spec, double length_scale, NoiseVariances* theta) {
  double max_rotation = 0.0, max_translation = 0.0;
  for (int k = 0; k < kNumNoiseComponents; ++k) {
    double& maximum = IsRotation(k) ? max_rotation : max_translation;
    maximum = std::max(maximum, (*theta)[k]);
  }
  const double L2 = length_scale * length_scale;
  for (int k = 0; k < kNumNoiseComponents; ++k) {
    if (spec.group[k] < 0) continue;
    const double relative =
        IsRotation(k) ? kRelativeFloor * max_translation / L2 : kRelativeFloor * max_rotation * L2;
    (*theta)[k] = std::max({(*theta)[k], relative, kAbsoluteFloor});
  }
}

// Starting values of the estimated groups from the raw residual energies.
void InitialVariances(const std::vector<StationLinearization>& stations,
                      const std::vector<bool>& included, const NoiseSpec& spec, double length_scale,
                      NoiseVariances* theta) {
  // Rotation groups first: they also explain part of the translation residuals (lever arms).
  for (int pass = 0; pass < 2; ++pass) {
    for (int g = 0; g < spec.NumGroups(); ++g) {
      std::vector<int> members;
      for (int k = 0; k < kNumNoiseComponents; ++k)
        if (spec.group[k] == g) members.push_back(k);
      const bool rotation_group = IsRotation(members.front());
      if (rotation_group != (pass == 0)) continue;
      if ((*theta)[members.front()] > 0.0) continue;  // caller's starting value
      const int block = rotation_group ? 0 : 3;
      double energy = 0.0, unit = 0.0, explained = 0.0;
      for (size_t i = 0; i < stations.size(); ++i) {
        if (!included[i]) continue;
        energy += stations[i].residual.segment<3>(block).squaredNorm();
        for (int k : members) unit += stations[i].components[k].block<3, 3>(block, block).trace();
        for (int k = 0; k < kNumNoiseComponents; ++k) {
          if (spec.group[k] == g || (*theta)[k] <= 0.0) continue;
          explained += (*theta)[k] * stations[i].components[k].block<3, 3>(block, block).trace();
        }
      }
      const double value = std::max(energy - explained, 0.01 * energy) / std::max(unit, 1e-300);
      for (int k : members) (*theta)[k] = value;
    }
  }
  ApplyFloors(spec, length_scale, theta);
}

// One Fisher-scoring (Helmert) step for the estimated groups; returns the new variances.
NoiseVariances VarianceStep(const std::vector<StationLinearization>& stations,
                            const std::vector<bool>& included, const NoiseSpec& spec,
                            const NoiseVariances& theta, double length_scale,
                            std::array<double, kMaxGroups>* dof = nullptr) {
  const int G = spec.NumGroups();
  const Refit refit = FeasibleRefit(stations, included, theta);
  const Matrix12d& Ni = refit.N_inverse;
  // Index G is the known part Q_0 = Σ_{known k} θ_k Q_k.
  const int M = G + 1;
  double q[kMaxGroups + 1] = {};
  double trace_WQ[kMaxGroups + 1] = {};
  double trace_WQWQ[kMaxGroups + 1][kMaxGroups + 1] = {};
  double trace_NiCross[kMaxGroups + 1][kMaxGroups + 1] = {};
  Matrix12d H[kMaxGroups + 1];
  for (int g = 0; g < M; ++g) H[g].setZero();
  // Per station only 6×6 and 6×12 products of fixed size (lazyProduct: Eigen's coefficient-based
  // kernel, not the general GEMM path), O(M²) 6×6 work and O(M) 12×12 outer products:
  //   tr(N⁻¹ JᵀWQ_gWQ_hWJ) = tr(WQ_gWQ_h · WJN⁻¹Jᵀ), so the cross term needs no 12×12 sum.
  for (size_t i = 0; i < stations.size(); ++i) {
    if (!included[i]) continue;
    const StationLinearization& s = stations[i];
    const Matrix6d& W = refit.inverse_covariance[i];
    const Vector6d r_hat = s.residual - s.jacobian * refit.delta;
    const Eigen::Matrix<double, 6, 12> WJ = W.lazyProduct(s.jacobian);
    const Eigen::Matrix<double, 6, 12> WJNi = WJ.lazyProduct(Ni);
    const Matrix6d leverage = WJNi.lazyProduct(s.jacobian.transpose());  // W J N⁻¹ Jᵀ
    const Vector6d Wr = W * r_hat;
    Matrix6d Q[kMaxGroups + 1], WQ[kMaxGroups + 1];
    for (int g = 0; g < M; ++g) Q[g].setZero();
    for (int k = 0; k < kNumNoiseComponents; ++k) {
      if (spec.group[k] >= 0)
        Q[spec.group[k]] += s.components[k];
      else
        Q[G] += theta[k] * s.components[k];
    }
    for (int g = 0; g < M; ++g) WQ[g] = W.lazyProduct(Q[g]);
    for (int g = 0; g < M; ++g) {
      q[g] += Wr.dot(Q[g] * Wr);
      trace_WQ[g] += WQ[g].trace();
      const Eigen::Matrix<double, 6, 12> QWJ = Q[g].lazyProduct(WJ);
      H[g].noalias() += WJ.transpose().lazyProduct(QWJ);
      for (int h = g; h < M; ++h) {
        const Matrix6d WQWQ = WQ[g].lazyProduct(WQ[h]);
        trace_WQWQ[g][h] += WQWQ.trace();
        trace_NiCross[g][h] += WQWQ.cwiseProduct(leverage.transpose()).sum();
      }
    }
  }
  // tr(P Q_g P Q_h) = tr(WQ_gWQ_h) − 2 tr(N⁻¹ JᵀWQ_gWQ_hWJ) + tr(N⁻¹H_g N⁻¹H_h).
  Matrix12d NiH[kMaxGroups + 1];
  for (int g = 0; g < M; ++g) NiH[g] = Ni * H[g];
  auto trace_PQPQ = [&](int g, int h) {
    const int a = std::min(g, h), b = std::max(g, h);
    return trace_WQWQ[a][b] - 2.0 * trace_NiCross[a][b] +
           NiH[g].cwiseProduct(NiH[h].transpose()).sum();
  };
  using GroupMatrix = Eigen::Matrix<double, kMaxGroups, kMaxGroups>;
  using GroupVector = Eigen::Matrix<double, kMaxGroups, 1>;
  GroupMatrix S = GroupMatrix::Identity();
  GroupVector rhs = GroupVector::Zero();
  for (int g = 0; g < G; ++g) {
    rhs(g) = q[g] - trace_PQPQ(g, G);
    for (int h = 0; h < G; ++h) S(g, h) = trace_PQPQ(g, h);
  }
  if (dof != nullptr) {
    // Var(θ̂_g) = 2 (S⁻¹)_gg (REML's Fisher information is S / 2); a χ²(ν) estimate has
    // Var = 2 θ² / ν, so ν_g = θ_g² / (S⁻¹)_gg.
    const Eigen::MatrixXd S_inverse = PseudoInverse(S.topLeftCorner(G, G));
    for (int g = 0; g < G; ++g) {
      double value = 0.0;
      for (int k = 0; k < kNumNoiseComponents; ++k)
        if (spec.group[k] == g) value = theta[k];
      (*dof)[g] = S_inverse(g, g) > 0.0 ? value * value / S_inverse(g, g) : 0.0;
    }
  }
  GroupVector solution = GroupVector::Zero();
  solution.head(G) = ColPivQrSolve(S.topLeftCorner(G, G), rhs.head(G));
  NoiseVariances next = theta;
  for (int g = 0; g < G; ++g) {
    int first = -1;
    for (int k = 0; k < kNumNoiseComponents; ++k)
      if (spec.group[k] == g && first < 0) first = k;
    double value = solution(g);
    if (!std::isfinite(value)) {
      // Förstner's ratio update: positive whenever the residual energy is.
      const double redundancy = trace_WQ[g] - NiH[g].trace();
      value = redundancy > 0.0 ? theta[first] * q[g] / redundancy : theta[first];
    }
    // A non-positive solution means the maximum is on the boundary θ_g = 0: approach it by at
    // most a factor 10 per step, until the floor holds it.
    value = std::max(value, kMaxDecrease * theta[first]);
    for (int k = 0; k < kNumNoiseComponents; ++k)
      if (spec.group[k] == g) next[k] = value;
  }
  ApplyFloors(spec, length_scale, &next);
  return next;
}

// A log-spaced grid per estimated group: log θ_g from low[g] to high[g].
struct LogGrid {
  int points = 0;
  std::array<double, kMaxGroups> low{}, high{};
  double Value(int g, int index) const {
    return std::exp(low[g] + (high[g] - low[g]) * index / (points - 1));
  }
};

// exp(ℓ_R) · Π_g θ_g^(1/2) (prior θ^(−1/2) times dθ = θ d log θ) on `grid`, integrated: the
// posterior means of the groups' σ, and per group the range of log θ_g where the weight exceeds
// e⁻²⁵ of its largest value.
struct GridIntegral {
  std::array<double, kMaxGroups> mean{}, low{}, high{};
  bool valid = false;
};

GridIntegral IntegrateOnGrid(const std::vector<StationLinearization>& stations,
                             const std::vector<bool>& included, const NoiseSpec& spec,
                             const NoiseVariances& base, const LogGrid& grid) {
  const int G = spec.NumGroups();
  int points = 1;
  for (int g = 0; g < G; ++g) points *= grid.points;
  std::vector<double> log_weight(static_cast<size_t>(points));
  std::vector<std::array<int, kMaxGroups>> index(static_cast<size_t>(points));
  double max_log_weight = -std::numeric_limits<double>::infinity();
  for (int p = 0; p < points; ++p) {
    NoiseVariances theta = base;
    double log_measure = 0.0;
    for (int g = 0, rest = p; g < G; ++g, rest /= grid.points) {
      index[p][g] = rest % grid.points;
      const double value = grid.Value(g, index[p][g]);
      log_measure += 0.5 * std::log(value);
      for (int k = 0; k < kNumNoiseComponents; ++k)
        if (spec.group[k] == g) theta[k] = value;
    }
    // −∞ at a grid corner too ill-conditioned to whiten (LinearRefit).
    log_weight[p] = LinearRefit(stations, included, theta).log_likelihood + log_measure;
    if (std::isfinite(log_weight[p])) max_log_weight = std::max(max_log_weight, log_weight[p]);
  }
  GridIntegral integral;
  if (!std::isfinite(max_log_weight)) return integral;
  integral.valid = true;
  std::array<int, kMaxGroups> first, last;
  first.fill(grid.points);
  last.fill(-1);
  double total = 0.0;
  for (int p = 0; p < points; ++p) {
    if (!std::isfinite(log_weight[p])) continue;
    const double weight = std::exp(log_weight[p] - max_log_weight);
    total += weight;
    for (int g = 0; g < G; ++g) {
      integral.mean[g] += weight * std::sqrt(grid.Value(g, index[p][g]));
      if (log_weight[p] - max_log_weight > -25.0) {
        first[g] = std::min(first[g], index[p][g]);
        last[g] = std::max(last[g], index[p][g]);
      }
    }
  }
  for (int g = 0; g < G; ++g) {
    integral.mean[g] /= total;
    integral.low[g] = std::log(grid.Value(g, first[g]));
    integral.high[g] = std::log(grid.Value(g, last[g]));
  }
  return integral;
}

// The estimated group variances as posterior mean σ, squared (header: "Posterior mean"); with
// more than kMaxJointGroups groups each one's conditional on the others at the REML point.
NoiseVariances PosteriorMean(const std::vector<StationLinearization>& stations,
                             const std::vector<bool>& included, const NoiseSpec& spec,
                             const NoiseVariances& reml) {
  const int G = spec.NumGroups();
  if (G > kMaxJointGroups) {
    NoiseVariances posterior = reml;
    for (int g = 0; g < G; ++g) {
      NoiseSpec one = spec;
      for (int k = 0; k < kNumNoiseComponents; ++k) one.group[k] = spec.group[k] == g ? 0 : -1;
      const NoiseVariances conditional = PosteriorMean(stations, included, one, reml);
      for (int k = 0; k < kNumNoiseComponents; ++k)
        if (spec.group[k] == g) posterior[k] = conditional[k];
    }
    return posterior;
  }
  // Coarse grid per group: up to 4 times the variance that alone would explain all the residual
  // energy of its block (an upper scale: other components explain part of it; at least the
  // REML estimate), down to 10⁻⁶ of it.
  LogGrid coarse;
  coarse.points = kCoarseGridPoints;
  for (int g = 0; g < G; ++g) {
    double energy = 0.0, unit = 0.0, reml_value = 0.0;
    bool rotation_group = false;
    for (int k = 0; k < kNumNoiseComponents; ++k) {
      if (spec.group[k] != g) continue;
      rotation_group = IsRotation(k);
      reml_value = reml[k];
    }
    const int block = rotation_group ? 0 : 3;
    for (size_t i = 0; i < stations.size(); ++i) {
      if (!included[i]) continue;
      energy += stations[i].residual.segment<3>(block).squaredNorm();
      for (int k = 0; k < kNumNoiseComponents; ++k)
        if (spec.group[k] == g) unit += stations[i].components[k].block<3, 3>(block, block).trace();
    }
    const double upper = std::max(energy / std::max(unit, 1e-300), reml_value);
    coarse.low[g] = std::log(kPosteriorGridLow * upper);
    coarse.high[g] = std::log(kPosteriorGridHigh * upper);
  }
  const GridIntegral first = IntegrateOnGrid(stations, included, spec, reml, coarse);
  if (!first.valid) return reml;
  // Fine grid over where the coarse weights are not negligible, one coarse step wider on each
  // side: a sharp likelihood (many degrees of freedom) is narrower than a coarse step.
  LogGrid fine;
  fine.points = kFineGridPoints;
  for (int g = 0; g < G; ++g) {
    const double step = (coarse.high[g] - coarse.low[g]) / (coarse.points - 1);
    fine.low[g] = first.low[g] - step;
    fine.high[g] = first.high[g] + step;
  }
  const GridIntegral second = IntegrateOnGrid(stations, included, spec, reml, fine);
  const GridIntegral& integral = second.valid ? second : first;
  NoiseVariances posterior = reml;
  for (int k = 0; k < kNumNoiseComponents; ++k)
    if (spec.group[k] >= 0)
      posterior[k] = integral.mean[spec.group[k]] * integral.mean[spec.group[k]];
  return posterior;
}

// r_wᵀ C_w⁺ r_w over the eigen-directions of C_w with eigenvalue above kRankFloor, and their
// count. Almost always C_w has full rank: then its Cholesky factor C_w = K Kᵀ gives the statistic
// ‖K⁻¹ r_w‖² directly, and ‖K⁻¹‖²_F < 1 / kRankFloor proves every eigenvalue above the floor
// (λ_min(C_w)⁻¹ = ‖K⁻¹‖²_2 ≤ ‖K⁻¹‖²_F), so the eigendecomposition — the costliest step of a test
// — is needed only near rank deficiency, with the same result.
struct Statistic {
  double value = 0.0;
  int dof = 0;
};
constexpr double kRankFloor = 1e-9;

Statistic WhitenedStatistic(const Matrix6d& C_white, const Vector6d& r_white) {
  const Eigen::LLT<Matrix6d> llt(C_white);
  if (llt.info() == Eigen::Success && (llt.matrixLLT().diagonal().array() > 0.0).all()) {
    const Matrix6d K_inverse = internal::LowerTriangularInverse(llt.matrixLLT());
    if (K_inverse.squaredNorm() < 1.0 / kRankFloor) return {(K_inverse * r_white).squaredNorm(), 6};
  }
  const Eigen::SelfAdjointEigenSolver<Matrix6d> eigen(C_white);
  Statistic statistic;
  for (int k = 0; k < 6; ++k) {
    const double lambda = eigen.eigenvalues()(k);
    if (lambda <= kRankFloor) continue;
    const double projection = eigen.eigenvectors().col(k).dot(r_white);
    statistic.value += projection * projection / lambda;
    ++statistic.dof;
  }
  return statistic;
}

}  // namespace

double MaxRelativeChange(const NoiseVariances& a, const NoiseVariances& b) {
  double change = 0.0;
  for (int k = 0; k < kNumNoiseComponents; ++k) {
    if (a[k] == b[k]) continue;
    change = std::max(change, std::abs(a[k] - b[k]) / std::max(std::abs(a[k]), std::abs(b[k])));
  }
  return change;
}

bool StationTestOptions::IsValid(std::string* why) const {
  if (false_alarm > 0.0 && false_alarm < 1.0) return true;
  return Invalid(why, "StationTestOptions.false_alarm", "must be a probability between 0 and 1",
                 "give the chance of flagging a good station, e.g. 0.0027 (3σ)");
}

std::vector<StationTest> TestStations(const std::vector<StationLinearization>& stations,
                                      const std::vector<bool>& included,
                                      const NoiseVariances& theta,
                                      const StationTestOptions& options) {
  RequireValid(options);
  const Refit refit = FeasibleRefit(stations, included, theta);
  std::vector<StationTest> tests(stations.size());
  std::vector<Vector6d> r_hat(stations.size());
  double energy = 0.0;  // Ω (header)
  int included_count = 0;
  for (size_t i = 0; i < stations.size(); ++i) {
    r_hat[i] = stations[i].residual - stations[i].jacobian * refit.delta;
    if (!included[i]) continue;
    energy += r_hat[i].dot(refit.inverse_covariance[i] * r_hat[i]);
    ++included_count;
  }
  const double nu = 6.0 * included_count - 12.0;
  // Thresholds on T_i per degrees of freedom d = 1..6, [0] included, [1] excluded.
  double threshold[7][2] = {};
  const double p = 1.0 - options.false_alarm;
  for (int d = 1; d <= 6; ++d) {
    const double chi2 = options.false_alarm == kThreeSigmaFalseAlarm
                            ? ThreeSigmaChiSquare(d)
                            : uncertainty::ChiSquareQuantile(p, d);
    threshold[d][0] = threshold[d][1] = chi2;
    // Never below χ² (header): a known part of Σ that overstates the noise makes Ω small.
    if (options.estimated && nu > d && energy > 0.0) {
      const double q_included = uncertainty::FisherQuantile(p, d, nu - d);
      threshold[d][0] = std::max(chi2, q_included * energy * d / (nu - d + q_included * d));
      threshold[d][1] = std::max(chi2, uncertainty::FisherQuantile(p, d, nu) * energy * d / nu);
    }
  }
  for (size_t i = 0; i < stations.size(); ++i) {
    const StationLinearization& s = stations[i];
    const Matrix6d& W = refit.inverse_covariance[i];
    StationTest& test = tests[i];
    test.chi2 = s.residual.dot(W * s.residual);
    const Matrix6d leverage =
        (s.jacobian.lazyProduct(refit.N_inverse)).lazyProduct(s.jacobian.transpose());
    const Matrix6d sigma = CombineComponents(s.components, theta);
    const Matrix6d C = included[i] ? Matrix6d(sigma - leverage) : Matrix6d(sigma + leverage);
    // Pseudo-inverse in the metric of Σ: whiten with Σ = L Lᵀ first, so the rank decision is
    // scale-free.
    const Eigen::LLT<Matrix6d> llt(sigma);
    const Matrix6d L_inverse = internal::LowerTriangularInverse(llt.matrixLLT());
    const Matrix6d C_white = L_inverse * C * L_inverse.transpose();
    const Vector6d r_white = L_inverse * r_hat[i];
    const auto [statistic, dof] = WhitenedStatistic(0.5 * (C_white + C_white.transpose()), r_white);
    test.statistic = statistic;
    test.dof = dof;
    test.threshold = threshold[dof][included[i] ? 0 : 1];
    test.outlier = dof > 0 && test.threshold > 0.0 && statistic > test.threshold;
  }
  return tests;
}

std::vector<StationLinearization> LinearizeStations(const handeye::Problem& problem, const Pose& X,
                                                    const Pose& Z) {
  // Appended, not sized up front: a sized vector value-initialises (zeroes) its 2.3 kB per
  // station first, a memset that was 16% of `calibrate --method ml` at 10⁵ stations (perf).
  std::vector<StationLinearization> stations;
  stations.reserve(problem.A.size());
  for (size_t i = 0; i < problem.A.size(); ++i) {
    Matrix6x12d jacobian;
    const Vector6d residual = LoopResidual(problem.A[i], problem.B[i], X, Z, &jacobian);
    stations.push_back(
        {residual, jacobian, StationNoiseComponents(problem.setup, problem.A[i], problem.B[i], X)});
  }
  return stations;
}

NoiseSpec NoiseSpec::FromSigmas(const std::optional<PoseSigma>& robot,
                                const std::optional<PoseSigma>& camera) {
  NoiseSpec spec;
  const PoseSigma zero;
  spec.variances = Variances(robot.value_or(zero), camera.value_or(zero));
  if (robot && camera) return spec;
  if (robot) {
    spec.group = {-1, -1, 0, 1, -1, -1};
    spec.variances[kCameraRotation] = spec.variances[kCameraTranslation] = 0.0;
  } else if (camera) {
    spec.group = {0, 1, -1, -1, -1, -1};
    spec.variances[kRobotRotation] = spec.variances[kRobotTranslation] = 0.0;
  } else {
    spec.group = {0, 1, 0, 1, -1, -1};
    spec.variances = {};
  }
  spec.posterior_mean = true;
  spec.richer = !camera;
  return spec;
}

bool NoiseSpec::AnyEstimated() const {
  return NumGroups() > 0;
}

int NoiseSpec::NumGroups() const {
  int groups = 0;
  for (int g : group) groups = std::max(groups, g + 1);
  return groups;
}

PoseSigma NoiseEstimate::robot() const {
  return {std::sqrt(variances[kRobotRotation]), std::sqrt(variances[kRobotTranslation])};
}

PoseSigma NoiseEstimate::camera() const {
  return {std::sqrt(variances[kCameraRotation]), std::sqrt(variances[kCameraTranslation])};
}

PoseSigma NoiseEstimate::camera_excess() const {
  return {std::sqrt(variances[kCameraTiltExcess]), std::sqrt(variances[kCameraDepthExcess])};
}

NoiseVariances InitialNoiseGuess(const std::vector<StationLinearization>& stations,
                                 const NoiseSpec& spec, double length_scale) {
  NoiseVariances theta = spec.variances;
  for (int k = 0; k < kNumNoiseComponents; ++k)
    if (spec.group[k] >= 0) theta[k] = 0.0;
  InitialVariances(stations, std::vector<bool>(stations.size(), true), spec, length_scale, &theta);
  return theta;
}

double ThreeSigmaChiSquare(int dof) {
  // Quantiles of χ²(dof) at p = erf(3/√2) = 0.99730020 (two-sided 3σ of a normal).
  static constexpr double kQuantile[7] = {0.0,          9.0,          11.829158082, 14.156413609,
                                          16.251340814, 18.205314008, 20.062086166};
  if (dof < 1 || dof > 6) throw std::invalid_argument("ThreeSigmaChiSquare: dof must be 1..6");
  return kQuantile[dof];
}

namespace {

// χ²(k) quantiles at 95% for k = 0..3 extra variances.
constexpr double kChiSquare95[4] = {0.0, 3.841, 5.991, 7.815};

// EstimateNoise for one model (no choice between models); *final_included: the stations the
// last variance estimate used.
NoiseEstimate EstimateOneModel(const std::vector<StationLinearization>& stations,
                               const NoiseSpec& spec, double length_scale,
                               std::vector<bool>* final_included,
                               std::array<double, kMaxGroups>* dof = nullptr) {
  const size_t n = stations.size();
  NoiseEstimate estimate;
  estimate.variances = estimate.reml_variances = spec.variances;
  std::vector<bool> included(n, true);
  const size_t max_excluded = (n - 3) / 2;
  if (spec.AnyEstimated())
    InitialVariances(stations, included, spec, length_scale, &estimate.variances);
  for (int round = 0; round < kMaxExclusionRounds; ++round) {
    if (spec.AnyEstimated()) {
      estimate.converged = false;
      double log_likelihood = LinearRefit(stations, included, estimate.variances).log_likelihood;
      for (int iteration = 0; iteration < kMaxVarianceIterations; ++iteration) {
        ++estimate.iterations;
        NoiseVariances next =
            VarianceStep(stations, included, spec, estimate.variances, length_scale);
        // Safeguard: the scoring step must not decrease ℓ_R (on a flat likelihood, iterated
        // MINQUE can cycle); halve it geometrically until it does not.
        double next_log_likelihood = LinearRefit(stations, included, next).log_likelihood;
        int halvings = 0;
        while (!(next_log_likelihood >= log_likelihood) && halvings < kMaxHalvings) {
          for (int k = 0; k < kNumNoiseComponents; ++k)
            if (spec.group[k] >= 0) next[k] = std::sqrt(next[k] * estimate.variances[k]);
          next_log_likelihood = LinearRefit(stations, included, next).log_likelihood;
          ++halvings;
        }
        if (!(next_log_likelihood >= log_likelihood)) {
          estimate.converged = true;  // no ascent left at working precision: the maximum
          break;
        }
        const double change = MaxRelativeChange(next, estimate.variances);
        estimate.variances = next;
        log_likelihood = next_log_likelihood;
        if (change < kTolerance) {
          estimate.converged = true;
          break;
        }
      }
      estimate.reml_variances = estimate.variances;
      if (dof != nullptr)
        VarianceStep(stations, included, spec, estimate.variances, length_scale, dof);
      if (spec.posterior_mean && n <= kPosteriorMaxStations) {
        // The grid's mean σ per group need not be a feasible point itself (each group's mean
        // lies within its grid, the combination not necessarily): keep the REML point then.
        const NoiseVariances posterior =
            PosteriorMean(stations, included, spec, estimate.reml_variances);
        if (LinearRefit(stations, included, posterior).feasible) estimate.variances = posterior;
      }
    }
    estimate.stations = TestStations(stations, included, estimate.variances);
    std::vector<bool> next_included(n, true);
    size_t flagged = 0;
    for (size_t i = 0; i < n; ++i) flagged += estimate.stations[i].outlier ? 1 : 0;
    if (flagged <= max_excluded) {
      for (size_t i = 0; i < n; ++i) next_included[i] = !estimate.stations[i].outlier;
    }
    size_t changed = 0;
    for (size_t i = 0; i < n; ++i) changed += next_included[i] != included[i] ? 1 : 0;
    if (static_cast<double>(changed) < kStableFlagsFraction * static_cast<double>(n)) break;
    included = next_included;
  }
  *final_included = included;
  return estimate;
}

// The isotropic model and the richer ones (header, "Richer noise models") fitted on `stations`,
// and the one the likelihood-ratio test and Akaike's score choose, with its spec.
struct ModelChoice {
  NoiseEstimate estimate;
  NoiseSpec spec;
};

ModelChoice ChooseModel(const std::vector<StationLinearization>& stations,
                        const NoiseSpec& isotropic, double length_scale) {
  std::vector<bool> included;
  NoiseEstimate estimate = EstimateOneModel(stations, isotropic, length_scale, &included);
  // The richer models (header), started from the isotropic REML point: the camera's tilt and
  // depth excess; with both sides estimated also the robot's rotation variance apart from the
  // camera's, alone and with the excess.
  struct Candidate {
    NoiseSpec spec;
    double threshold = 0.0;  // χ²(extra variances) at 95%
  };
  std::vector<Candidate> candidates;
  const int G = isotropic.NumGroups();
  const bool split = isotropic.group[kRobotRotation] >= 0 &&
                     isotropic.group[kRobotRotation] == isotropic.group[kCameraRotation];
  for (int shape = 0; shape < 3; ++shape) {
    const bool excess = shape != 1, separate = shape != 0;
    if (separate && !split) continue;
    NoiseSpec rich = isotropic;
    rich.variances = estimate.reml_variances;
    int groups = G;
    if (separate) rich.group[kRobotRotation] = groups++;
    if (excess) {
      rich.group[kCameraTiltExcess] = groups++;
      rich.group[kCameraDepthExcess] = groups++;
      rich.variances[kCameraTiltExcess] = 0.1 * rich.variances[kCameraRotation];
      rich.variances[kCameraDepthExcess] = 0.1 * rich.variances[kCameraTranslation];
    }
    if (groups > kMaxGroups) continue;
    candidates.push_back({rich, kChiSquare95[groups - G]});
  }
  // Each compared with the isotropic maximum on the stations the isotropic model kept; of those
  // the test prefers, the one of largest ℓ_R − (extra variances) (Akaike).
  const double isotropic_likelihood =
      LinearRefit(stations, included, estimate.reml_variances).log_likelihood;
  NoiseEstimate best = estimate;
  NoiseSpec best_spec = isotropic;
  double best_score = isotropic_likelihood;
  for (const Candidate& candidate : candidates) {
    std::vector<bool> rich_included;
    std::array<double, kMaxGroups> dof{};
    NoiseEstimate fit;
    try {
      fit = EstimateOneModel(stations, candidate.spec, length_scale, &rich_included, &dof);
    } catch (const DegenerateError&) {
      continue;  // the data cannot support this model's variances: not a candidate
    }
    // Groups 0 … G − 1 are the isotropic model's: none may be left undetermined (header).
    if (!std::all_of(dof.begin(), dof.begin() + G, [](double v) { return v > kMinGroupDof; }))
      continue;
    const double likelihood = LinearRefit(stations, included, fit.reml_variances).log_likelihood;
    const double ratio = 2.0 * (likelihood - isotropic_likelihood);
    if (!std::isfinite(ratio)) continue;
    estimate.likelihood_ratio = std::max(estimate.likelihood_ratio, ratio);
    const double score = likelihood - (candidate.spec.NumGroups() - G);
    if (ratio > candidate.threshold && score > best_score) {
      best = fit;
      best.richer = true;
      best.likelihood_ratio = ratio;
      best.iterations += estimate.iterations;
      best_score = score;
      best_spec = candidate.spec;
    }
  }
  if (!best.richer) best.likelihood_ratio = estimate.likelihood_ratio;
  return {best, best_spec};
}

}  // namespace

NoiseEstimate EstimateNoise(const std::vector<StationLinearization>& stations,
                            const NoiseSpec& spec, double length_scale) {
  const size_t n = stations.size();
  if (n < 3) {
    throw DegenerateError("the noise model from fewer than 3 stations",
                          "record at least 3 stations");
  }
  if (spec.NumGroups() > kMaxGroups) {
    throw std::invalid_argument("EstimateNoise supports at most four variance groups");
  }
  NoiseSpec isotropic = spec;
  isotropic.richer = false;
  if (spec.richer) {
    for (int k : {kCameraTiltExcess, kCameraDepthExcess}) {
      isotropic.group[k] = -1;
      isotropic.variances[k] = 0.0;
    }
  }
  // A starting value from a richer model (ml alternates noise and pose estimates) may differ
  // within a group; start each group at its first member's value.
  for (int g = 0; g < isotropic.NumGroups(); ++g) {
    int first = -1;
    for (int k = 0; k < kNumNoiseComponents; ++k) {
      if (isotropic.group[k] != g) continue;
      if (first < 0) first = k;
      isotropic.variances[k] = isotropic.variances[first];
    }
  }
  if (!spec.richer || n < kAnisotropicMinStations) {
    std::vector<bool> included;
    return EstimateOneModel(stations, isotropic, length_scale, &included);
  }
  if (n <= kModelChoiceStations) return ChooseModel(stations, isotropic, length_scale).estimate;
  // The model chosen on kModelChoiceStations stations evenly spread over the recording (the
  // whole trajectory, header "Model choice at scale"), fitted on all from the subsample's REML
  // point: one fit of O(n) instead of four.
  std::vector<StationLinearization> subsample;
  subsample.reserve(kModelChoiceStations);
  for (size_t j = 0; j < kModelChoiceStations; ++j)
    subsample.push_back(stations[j * n / kModelChoiceStations]);
  const ModelChoice choice = ChooseModel(subsample, isotropic, length_scale);
  NoiseSpec chosen = choice.spec;
  chosen.variances = choice.estimate.reml_variances;
  std::vector<bool> included;
  NoiseEstimate estimate = EstimateOneModel(stations, chosen, length_scale, &included);
  estimate.richer = choice.estimate.richer;
  estimate.likelihood_ratio = choice.estimate.likelihood_ratio;
  estimate.iterations += choice.estimate.iterations;
  return estimate;
}

}  // namespace hecal::estimation
