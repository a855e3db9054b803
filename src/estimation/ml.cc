#include "hecal/estimation/ml.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/estimation/initialization.h"
#include "hecal/estimation/station_covariance.h"
#include "hecal/estimation/student_t.h"
#include "hecal/geometry/dense_decompositions.h"
#include "hecal/uncertainty/consistency.h"
#include "loop_solver.h"
#include "multi_start.h"

namespace hecal::estimation {
namespace {

using internal::Matrix12d;

constexpr double kRefreshRotation = 1e-3;     // rad: re-evaluate Σ_i when X moved more
constexpr double kRefreshTranslation = 1e-3;  // × L
constexpr int kMaxRefreshes = 5;
constexpr double kNoiseTolerance = 1e-3;  // relative change of the variances
constexpr double kFitLevel = 0.999;       // χ² point of the fit test of "Starts on demand"

struct Evaluation {
  double cost = 0.0;  // Σ ρ(r_iᵀ Σ_i⁻¹ r_i)
  double nll = 0.0;   // cost + Σ log det Σ_i
};

class MlSolver {
 public:
  MlSolver(const handeye::Problem& problem, const MlOptions& options)
      : problem_(problem),
        length_scale_(handeye::LengthScale(problem)),
        loss_(MakeLoss(options.robust_loss, options.robust_scale)),
        station_scale_(options.station_scale),
        fixed_(options.fixed) {}

  double length_scale() const { return length_scale_; }
  size_t stations() const { return problem_.A.size(); }
  int solves() const { return solves_; }
  // Per-station multipliers of Σ_i (empty: 1).
  void set_station_scale(std::vector<double> scale) { station_scale_ = std::move(scale); }

  // Square roots W_i of Σ_i⁻¹ at X.
  std::vector<Matrix6d> Whitening(const Pose& X, const NoiseVariances& theta) const {
    std::vector<Matrix6d> W(problem_.A.size());
    for (size_t i = 0; i < W.size(); ++i) {
      const double scale = station_scale_.empty() ? 1.0 : station_scale_[i];
      W[i] = WhiteningMatrix(
          scale * StationCovarianceOf(problem_.setup, problem_.A[i], problem_.B[i], X, theta));
    }
    return W;
  }

  Evaluation Evaluate(const handeye::Solution& solution, const NoiseVariances& theta) const {
    const std::vector<Matrix6d> W = Whitening(solution.X, theta);
    Evaluation evaluation;
    evaluation.cost = CostWith(solution, W);
    // W is triangular with det W = det(Σ)^(−1/2).
    double log_det = 0.0;
    for (const Matrix6d& W_i : W) log_det -= 2.0 * W_i.diagonal().array().abs().log().sum();
    evaluation.nll = evaluation.cost + log_det;
    return evaluation;
  }

  // Minimises with Σ_i at the current X, re-evaluating Σ_i until X stops moving.
  handeye::Solution Solve(const handeye::Solution& start, const NoiseVariances& theta) {
    handeye::Solution current = start;
    for (int refresh = 0; refresh < kMaxRefreshes; ++refresh) {
      const handeye::Solution weights_at = current;
      current = SolveOnce(current, Whitening(current.X, theta));
      if (internal::NearSolution(current, weights_at, kRefreshRotation,
                                 kRefreshTranslation * length_scale_)) {
        break;
      }
    }
    return current;
  }

  // One minimisation with the given whitening (Σ_i fixed).
  handeye::Solution SolveWith(const handeye::Solution& start, const std::vector<Matrix6d>& W) {
    return SolveOnce(start, W);
  }

  // Σ ρ(|W_i r_i|²) with the given whitening.
  double CostWith(const handeye::Solution& solution, const std::vector<Matrix6d>& W) const {
    return internal::LoopCostValue(problem_, W, loss_.get(), solution);
  }

  // Gauss–Newton inverse information at the solution, robust weights ρ'(s_i).
  Matrix12d Covariance(const handeye::Solution& solution, const NoiseVariances& theta) const {
    const Matrix12d information =
        internal::LinearizeLoopCost(problem_, Whitening(solution.X, theta), loss_.get(), solution)
            .hessian;
    if (fixed_) return handeye::ConstrainedInverse(information, solution, *fixed_);
    const Eigen::LLT<Matrix12d> llt(information);
    if (llt.info() == Eigen::Success) return llt.solve(Matrix12d::Identity());
    return PseudoInverse12(information);
  }

 private:
  handeye::Solution SolveOnce(const handeye::Solution& start, const std::vector<Matrix6d>& W) {
    ++solves_;
    return internal::MinimizeLoopCost(problem_, W, loss_.get(), start, fixed_ ? &*fixed_ : nullptr);
  }

  const handeye::Problem& problem_;
  double length_scale_;
  std::unique_ptr<ceres::LossFunction> loss_;
  std::vector<double> station_scale_;
  std::optional<handeye::FixedTranslation> fixed_;
  int solves_ = 0;
};

// The multi-start with one common whitening, Σ_i at the start of lowest negative log-likelihood
// (Σ_i depends on X only through lever arms, so the minima are where they would be with per-start
// weights, and the costs compare directly); then Σ_i is refreshed at the winner. Sets the start
// counts of `result` when it is not null.
handeye::Solution RefineStarts(MlSolver& solver, const std::vector<handeye::Solution>& starts,
                               const NoiseVariances& theta, MlResult* result) {
  size_t best_start = 0;
  if (starts.size() > 1) {
    std::vector<double> start_nll(starts.size());
    for (size_t i = 0; i < starts.size(); ++i) {
      start_nll[i] = solver.Evaluate(starts[i], theta).nll;
      if (start_nll[i] < start_nll[best_start]) best_start = i;
    }
  }
  const std::vector<Matrix6d> common = solver.Whitening(starts[best_start].X, theta);
  const internal::MultiStartResult multi = internal::RunMultiStart(
      starts, solver.length_scale(),
      [&](const handeye::Solution& start) { return solver.CostWith(start, common); },
      [&](const handeye::Solution& start) {
        const handeye::Solution optimum = solver.SolveWith(start, common);
        return internal::Optimum{optimum, solver.CostWith(optimum, common)};
      });
  if (result != nullptr) {
    result->starts_refined = multi.starts_refined;
    result->distinct_minima = multi.distinct_minima;
  }
  return solver.Solve(multi.best.solution, theta);
}

// "Starts on demand" (header): the optimum `best` reached from `starts` is trusted when some start
// lies within the basin distance of multi_start.h of it and, with both sigmas given and no robust
// loss, its Gaussian cost is within the χ²(6n − 12) 99.9% point.
bool MayBeWrongMinimum(const MlSolver& solver, const std::vector<handeye::Solution>& starts,
                       const handeye::Solution& best, const NoiseVariances& theta,
                       const NoiseSpec& spec, const MlOptions& options) {
  const double L = solver.length_scale();
  const bool near_a_start =
      std::any_of(starts.begin(), starts.end(), [&](const handeye::Solution& start) {
        return internal::NearSolution(start, best, internal::kBasinRotation,
                                      internal::kBasinTranslation * L);
      });
  if (!near_a_start) return true;
  if (spec.AnyEstimated() || options.robust_loss != RobustLoss::kNone) return false;
  const double dof = 6.0 * static_cast<double>(solver.stations()) - (options.fixed ? 11.0 : 12.0);
  return !(uncertainty::ChiSquareCdf(solver.Evaluate(best, theta).cost, dof) <= kFitLevel);
}

void CheckStations(const handeye::Problem& problem, const MlOptions& options) {
  if (problem.A.size() != problem.B.size()) {
    throw std::invalid_argument("RefineMl: one camera pose per robot pose");
  }
  if (!options.station_scale.empty() && options.station_scale.size() != problem.A.size()) {
    throw std::invalid_argument("RefineMl: one station_scale entry per station");
  }
  if (problem.A.size() < 3) {
    throw DegenerateError("X and Z from fewer than 3 stations", "record at least 3 stations");
  }
}

// q_i = r_iᵀ S_i⁻¹ r_i, S_i = Σ_k θ_k Q_ik.
std::vector<double> MahalanobisDistances(const std::vector<StationLinearization>& stations,
                                         const NoiseVariances& theta) {
  std::vector<double> q(stations.size());
  for (size_t i = 0; i < stations.size(); ++i) {
    const Matrix6d S = CombineComponents(stations[i].components, theta);
    q[i] = stations[i].residual.dot(S.ldlt().solve(stations[i].residual));
  }
  return q;
}

}  // namespace

bool MlOptions::IsValid(std::string* why) const {
  const auto bad = [](const std::optional<PoseSigma>& sigma) {
    return sigma && !(sigma->rotation >= 0.0 && std::isfinite(sigma->rotation) &&
                      sigma->translation >= 0.0 && std::isfinite(sigma->translation));
  };
  if (bad(robot_sigma) || bad(camera_sigma)) {
    return Invalid(why, bad(robot_sigma) ? "MlOptions.robot_sigma" : "MlOptions.camera_sigma",
                   "sigmas must be finite and non-negative", "give values >= 0 (radians, metres)");
  }
  if (!(robust_scale > 0.0) || !std::isfinite(robust_scale)) {
    return Invalid(why, "MlOptions.robust_scale", "the robust loss scale must be positive",
                   "use e.g. 1.83 (whitened units per component: the 3-sigma outlier level)");
  }
  for (double scale : station_scale) {
    if (!(scale > 0.0) || !std::isfinite(scale)) {
      return Invalid(why, "MlOptions.station_scale",
                     "a station's covariance multiplier must be positive and finite",
                     "give values > 0, or none for 1 everywhere");
    }
  }
  if (max_noise_iterations < 1) {
    return Invalid(why, "MlOptions.max_noise_iterations",
                   "must be at least 1, got " + std::to_string(max_noise_iterations),
                   "use e.g. 10");
  }
  return true;
}

MlResult RefineMl(const handeye::Problem& problem, const std::vector<handeye::Solution>& starts,
                  const MlOptions& options) {
  RequireValid(options);
  if (starts.empty()) throw std::invalid_argument("RefineMl: no starting solution");
  CheckStations(problem, options);
  MlSolver solver(problem, options);
  const double L = solver.length_scale();
  NoiseSpec spec = NoiseSpec::FromSigmas(options.robot_sigma, options.camera_sigma);
  if (!spec.AnyEstimated())
    spec.variances = Variances(*options.robot_sigma, *options.camera_sigma, options.camera_excess);

  // Initial noise model: the known values, and for the unknown ones the smallest residual-based
  // guess over the starts (a wrong start has large residuals and would overstate the noise).
  NoiseVariances theta = spec.variances;
  if (spec.AnyEstimated()) {
    for (int k = 0; k < kNumNoiseComponents; ++k)
      if (spec.group[k] >= 0) theta[k] = std::numeric_limits<double>::infinity();
    for (const handeye::Solution& start : starts) {
      const NoiseVariances guess =
          InitialNoiseGuess(LinearizeStations(problem, start.X, start.Z), spec, L);
      for (int k = 0; k < kNumNoiseComponents; ++k)
        if (spec.group[k] >= 0) theta[k] = std::min(theta[k], guess[k]);
    }
  }

  MlResult result;
  handeye::Solution best = RefineStarts(solver, starts, theta, &result);
  // With a fixed component the closed forms do not apply (parallel axes): the caller's starts.
  if (options.starts_on_demand && !options.fixed &&
      MayBeWrongMinimum(solver, starts, best, theta, spec, options)) {
    std::vector<handeye::Solution> more = starts;
    for (const handeye::Solution& start : Solutions(InitialSolutions(problem)))
      more.push_back(start);
    best = RefineStarts(solver, more, theta, &result);
  }

  // Alternate the noise estimate and the pose estimate.
  NoiseSpec current = spec;
  for (int iteration = 0; iteration < options.max_noise_iterations; ++iteration) {
    current.variances = theta;
    result.noise = EstimateNoise(LinearizeStations(problem, best.X, best.Z), current, L);
    if (!spec.AnyEstimated()) break;
    const double change = MaxRelativeChange(theta, result.noise.variances);
    theta = result.noise.variances;
    if (change < kNoiseTolerance) break;
    best = solver.Solve(best, theta);
  }

  result.X = best.X;
  result.Z = best.Z;
  result.covariance = solver.Covariance(best, theta);
  result.sigmas_estimated = spec.AnyEstimated();
  result.cost = solver.Evaluate(best, theta).cost;
  result.solves = solver.solves();
  if (options.heavy_tails) FitHeavyTails(problem, options, &result);
  return result;
}

void FitHeavyTails(const handeye::Problem& problem, const MlOptions& options, MlResult* ml) {
  RequireValid(options);
  CheckStations(problem, options);
  const NoiseSpec spec = NoiseSpec::FromSigmas(options.robot_sigma, options.camera_sigma);
  const size_t n = problem.A.size();
  // Both sides estimated only: a station's latent scale would rescale a given sigma too.
  if (options.robot_sigma || options.camera_sigma || n < kStudentTMinStations ||
      options.robust_loss != RobustLoss::kNone) {
    return;
  }
  constexpr int d = 6;
  std::vector<StationLinearization> stations = LinearizeStations(problem, ml->X, ml->Z);
  const StudentTChoice choice =
      ChooseStudentT(MahalanobisDistances(stations, ml->noise.reml_variances), d);
  ml->noise.student_t_ratio = choice.likelihood_ratio;
  if (!choice.chosen) return;

  // EM (student_t.h): weights at the current fit, variance components on Q_ik / w_i, pose with
  // Σ_i = κ_ν S_i / w_i.
  MlSolver solver(problem, options);
  const double L = solver.length_scale();
  const double kappa = StudentTInformationFactor(choice.dof, d);
  NoiseVariances scale = ml->noise.reml_variances;
  for (double& variance : scale) variance *= choice.scale;
  handeye::Solution best{ml->X, ml->Z};
  NoiseSpec current = spec;
  NoiseEstimate noise;
  std::vector<double> station_scale(n);
  for (int iteration = 0; iteration < options.max_noise_iterations; ++iteration) {
    if (iteration > 0) stations = LinearizeStations(problem, best.X, best.Z);
    const std::vector<double> q = MahalanobisDistances(stations, scale);
    std::vector<StationLinearization> weighted = stations;
    for (size_t i = 0; i < n; ++i) {
      const double w = StudentTWeight(q[i], choice.dof, d);
      for (Matrix6d& Q : weighted[i].components) Q /= w;
      station_scale[i] = kappa / w;
    }
    current.variances = scale;
    noise = EstimateNoise(weighted, current, L);
    const double change = MaxRelativeChange(scale, noise.reml_variances);
    scale = noise.reml_variances;
    solver.set_station_scale(station_scale);
    best = solver.Solve(best, noise.variances);
    if (change < kNoiseTolerance) break;
  }
  // The outlier flags stay the Gaussian fit's (student_t.h, "What is an outlier").
  noise.stations = std::move(ml->noise.stations);
  noise.student_t_dof = choice.dof;
  noise.student_t_ratio = choice.likelihood_ratio;
  noise.station_scale = std::move(station_scale);
  ml->X = best.X;
  ml->Z = best.Z;
  ml->covariance = solver.Covariance(best, noise.variances);
  ml->cost = solver.Evaluate(best, noise.variances).cost;
  ml->solves += solver.solves();
  ml->noise = std::move(noise);
}

handeye::Solution RefineMlFromGoodStart(const handeye::Problem& problem,
                                        const handeye::Solution& start, const MlOptions& options) {
  RequireValid(options);
  CheckStations(problem, options);
  if (!options.robot_sigma || !options.camera_sigma) {
    throw InputError("MlOptions.robot_sigma", 0,
                     "refining from a good start needs both the robot and the camera sigma",
                     "set robot_sigma and camera_sigma");
  }
  MlSolver solver(problem, options);
  return RefineStarts(solver, {start},
                      Variances(*options.robot_sigma, *options.camera_sigma, options.camera_excess),
                      nullptr);
}

}  // namespace hecal::estimation
