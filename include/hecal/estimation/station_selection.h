// Which stations a calibration uses: gross outliers are rejected by consensus, then every
// station is tested at the noise level of the others (`hecal calibrate` does this by default;
// --keep-outliers turns it off).
//
// 1. Consensus (handeye/station_consensus.h): least median of squares over minimal sets of three
//    stations, with a local refit. It needs no noise level and leaves the candidate set
//    untouched by up to half the stations being arbitrary poses.
// 2. Test (noise_estimation.h, Baarda's data snooping in its multivariate form): `ml` (ml.h) on
//    the candidate set, with the given sigmas or the noise estimated from those stations only;
//    then every station's statistic at that fit — for a station of the set its residual against
//    its residual covariance, for a station outside it the prediction from the set — against
//    its quantile at the level below (under the Gaussian model: these fits do not try the
//    heavy-tailed Student-t model, student_t.h, which Calibrate fits on the stations kept).
//    The set becomes the stations that pass, and
//    1–2 repeat from the fit on it until it is stable (at most 5 rounds; ml restarts from the
//    previous round's fit, not from every closed form). A station that the
//    consensus left out but that fits the noise of the others comes back; one that the
//    consensus kept but fails the test is rejected.
// Level. A good station is rejected from a clean data set with probability kFalseRejection,
// whatever its size: each station is tested at α = 1 − (1 − kFalseRejection)^(1/n) (Šidák;
// 0.13% at n = 8, 3.4·10⁻⁴ at n = 30), because what costs the user is a data set that lost a
// good station, and at a fixed level per station that grows with n (0.27% per station, the
// two-sided 3σ level used before: 2.1% of the sets at n = 8, 7.8% at n = 30). With the noise
// estimated from the candidate set (a sigma not given) the statistic is judged against F, not
// χ² (noise_estimation.h, "Estimated variances"): the scale of 7 other stations is itself
// uncertain, and the χ² reference rejected a good station in 4.5% of clean 8-station sets
// (measured: docs/uncertainty.md, "Outlier test at few stations"). Gross outliers are far beyond
// either threshold (docs/troubleshooting.md, "Gross outliers": all found, k = 1, 2, 4 of 20).
// Guards: at most ⌊(n − 3)/2⌋ stations are rejected. When the test flags more, the data as a whole
// do not fit one rigid setup under the noise model (wrong conventions, wrong pairing, noise far
// from the model): nothing is rejected, `too_many` is set and the caller warns. A degeneracy
// verdict (handeye/observability.h) is reached on the candidate set, so a single gross outlier can
// neither create nor hide one.
//
// Reuse: when the last round's fit is ml from every closed-form start on exactly the stations
// kept (the set did not change after the first round — the usual case, the consensus having
// left the gross outliers out), it is returned as `fit`, and Calibrate (calibrate.h) with method
// ml, the same sigmas and no robust loss uses it instead of solving the same problem from the same
// starts again (bit for bit the same result). A fit of a later round, started from the previous
// round's fit only, is not returned: the final solve keeps its multi-start.
//
// Cost: the consensus (RequiredHypotheses(n) Shah solves of 3 stations — 149 at n = 20, 197 at
// n = 50 — scored on ≤ 2000 stations) and 1–5 `ml` solves; with the sigmas given about 1.6 ms at
// n = 20 and 3.8 ms at n = 50 (thesis protocol, 0.1 mm / 0.1°), of which the reused `fit` is
// 0.7 ms and 2.3 ms.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "hecal/estimation/ml.h"
#include "hecal/estimation/noise_estimation.h"
#include "hecal/estimation/pose_sigma.h"
#include "hecal/handeye/planar.h"
#include "hecal/handeye/problem.h"
#include "hecal/handeye/station_consensus.h"

namespace hecal::estimation {

// The probability that a clean data set loses a good station (header, "Level").
inline constexpr double kFalseRejection = 0.01;

struct StationSelectionOptions {
  std::optional<PoseSigma> robot_sigma;   // given; estimated from the set when absent
  std::optional<PoseSigma> camera_sigma;  // given; estimated from the set when absent
  // Camera poses measured by PnP: each station's own covariance of T_camera_target (right,
  // (ω, v)). When given (one per station), the test uses them as the known camera noise —
  // a PnP pose's precision varies strongly between views (distance, tilt, points seen), which
  // one isotropic camera sigma cannot describe — and estimates the robot noise (unless given)
  // next to them; camera_sigma then only weights the ml fit.
  std::vector<Matrix6d> camera_covariances;
  handeye::ConsensusOptions consensus;
  // Planar robots (handeye/planar.h): one component of X's translation given; the fits keep it,
  // start from handeye::FixedStart, and the consensus (closed forms on subsets, which planar data
  // do not determine) is skipped: the rounds start from every station.
  std::optional<handeye::TranslationFix> fix;

  // core/options_check.h: false naming StationSelectionOptions.robot_sigma / .camera_sigma
  // outside pose_sigma.h's range, .camera_covariances with a non-finite entry, or a
  // ConsensusOptions field.
  bool IsValid(std::string* why) const;
};

struct StationSelection {
  std::vector<bool> used;          // one flag per station of the problem
  std::vector<StationTest> tests;  // per station, at the last fit (statistic, dof, outlier)
  handeye::StationConsensus consensus;
  int flagged = 0;        // stations the last test flagged
  bool too_many = false;  // flagged > ⌊(n − 3)/2⌋: nothing rejected
  int rounds = 0;         // fit-and-test rounds run
  // ml on exactly the `used` stations from every closed-form start, with the sigmas fit_*_sigma
  // (estimated when absent) and no robust loss — set when the first round's set was kept.
  std::optional<MlResult> fit;
  std::optional<PoseSigma> fit_robot_sigma, fit_camera_sigma;

  std::vector<int> Rejected() const;  // indices of the stations not used, ascending
};

// Throws DegenerateError (fewer than 3 stations, or a candidate set that does not fix X and Z)
// and what RefineMl throws.
StationSelection SelectStations(const handeye::Problem& problem,
                                const StationSelectionOptions& options);

// Every station used (what --keep-outliers means).
StationSelection AllStations(size_t n);

// The indices of the true entries of `flags` (the stations used, or those flagged), ascending.
std::vector<int> TrueIndices(const std::vector<bool>& flags);

}  // namespace hecal::estimation
