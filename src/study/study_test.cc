#include "hecal/study/study.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "hecal/core/error.h"
#include "hecal/estimation/calibrate.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/geometry/se3.h"
#include "hecal/geometry/so3.h"
#include "hecal/sim/thesis_protocol.h"
#include "hecal/study/study_csv.h"
#include "hecal/uncertainty/consistency.h"

namespace hecal::study {
namespace {

Setting MakeSetting(handeye::Setup setup, int stations, double mm, double deg,
                    NoiseOn on = NoiseOn::kBoth,
                    sim::NoiseModel::Kind kind = sim::NoiseModel::Kind::kGaussian) {
  Setting s;
  s.setup = setup;
  s.stations = stations;
  s.noise_on = on;
  s.noise_kind = kind;
  s.translation_sigma = mm * 1e-3;
  s.rotation_sigma = deg * kRadiansPerDegree;
  return s;
}

TEST(PoseError, AngleOfRelativeRotationAndTranslationDistance) {
  const Pose truth = MakePose(so3::Exp(Eigen::Vector3d(0.3, -0.2, 0.1)), Eigen::Vector3d(1, 2, 3));
  Pose estimate = truth;
  estimate.linear() = truth.linear() * so3::Exp(Eigen::Vector3d(0.0, 0.0, 0.1));
  estimate.translation() += Eigen::Vector3d(3.0, 4.0, 0.0);
  const RotationTranslation error = PoseError(estimate, truth);
  EXPECT_NEAR(error.rotation, 0.1, 1e-12);
  EXPECT_NEAR(error.translation, 5.0, 1e-12);
}

TEST(NoiseSigmas, DeviceSelectionAndUniformScaling) {
  const Setting robot_only = MakeSetting(handeye::Setup::kEyeInHand, 5, 1.0, 2.0, NoiseOn::kRobot);
  EXPECT_NEAR(RobotSigma(robot_only).translation, 1e-3, 1e-15);
  EXPECT_NEAR(RobotSigma(robot_only).rotation, 2.0 * kRadiansPerDegree, 1e-15);
  EXPECT_EQ(CameraSigma(robot_only).translation, 0.0);
  EXPECT_EQ(CameraSigma(robot_only).rotation, 0.0);
  const Setting uniform = MakeSetting(handeye::Setup::kEyeInHand, 5, 3.0, 3.0, NoiseOn::kCamera,
                                      sim::NoiseModel::Kind::kUniform);
  EXPECT_NEAR(CameraSigma(uniform).translation, 3e-3 / std::sqrt(3.0), 1e-15);
  EXPECT_EQ(RobotSigma(uniform).translation, 0.0);
}

TEST(NoiseOn, ParsesTheCliSpellings) {
  EXPECT_EQ(ParseNoiseOn("robot"), NoiseOn::kRobot);
  EXPECT_EQ(ParseNoiseOn("both"), NoiseOn::kBoth);
  EXPECT_FALSE(ParseNoiseOn("Both").has_value());
  EXPECT_EQ(NoiseOnName(NoiseOn::kCamera), "camera");
}

TEST(TrialSeed, DependsOnEverythingButTheNoise) {
  const uint64_t a = TrialSeed(1, handeye::Setup::kEyeInHand, 10, 0);
  EXPECT_EQ(a, TrialSeed(1, handeye::Setup::kEyeInHand, 10, 0));
  EXPECT_NE(a, TrialSeed(2, handeye::Setup::kEyeInHand, 10, 0));
  EXPECT_NE(a, TrialSeed(1, handeye::Setup::kEyeToHand, 10, 0));
  EXPECT_NE(a, TrialSeed(1, handeye::Setup::kEyeInHand, 11, 0));
  EXPECT_NE(a, TrialSeed(1, handeye::Setup::kEyeInHand, 10, 1));
}

TEST(ValidateStudyOptions, RejectsUnusableOptions) {
  StudyOptions options;
  options.methods = {estimation::Method::kParkMartin};
  EXPECT_THROW(ValidateStudyOptions(options), InputError);  // no setting
  options.settings = {MakeSetting(handeye::Setup::kEyeInHand, 2, 0.0, 0.0)};
  EXPECT_THROW(ValidateStudyOptions(options), InputError);  // 2 stations
  options.settings = {MakeSetting(handeye::Setup::kEyeInHand, 3, -1.0, 0.0)};
  EXPECT_THROW(ValidateStudyOptions(options), InputError);  // negative sigma
  options.settings = {MakeSetting(handeye::Setup::kEyeInHand, 3, 0.0, 0.0)};
  options.trials = 0;
  EXPECT_THROW(ValidateStudyOptions(options), InputError);
  options.trials = 1;
  EXPECT_NO_THROW(ValidateStudyOptions(options));
  options.methods.clear();
  EXPECT_THROW(ValidateStudyOptions(options), InputError);
}

StudyOptions SmallStudy(int threads) {
  StudyOptions options;
  options.settings = {MakeSetting(handeye::Setup::kEyeInHand, 5, 0.0, 0.0),
                      MakeSetting(handeye::Setup::kEyeInHand, 5, 0.5, 0.5),
                      MakeSetting(handeye::Setup::kEyeToHand, 4, 0.5, 0.5, NoiseOn::kRobot,
                                  sim::NoiseModel::Kind::kUniform)};
  options.methods = {estimation::Method::kParkMartin, estimation::Method::kAndreff,
                     estimation::Method::kMl};
  options.trials = 6;
  options.seed = 42;
  options.threads = threads;
  return options;
}

TEST(RunStudy, SameSeedSameFilesWhateverTheThreadCount) {
  const StudyResult one = RunStudy(SmallStudy(1));
  const StudyResult two = RunStudy(SmallStudy(2));
  const StudyResult three = RunStudy(SmallStudy(3));
  EXPECT_EQ(TrialsCsv(one), TrialsCsv(two));
  EXPECT_EQ(TrialsCsv(one), TrialsCsv(three));
  EXPECT_EQ(SummaryCsv(one), SummaryCsv(two));
  StudyOptions other_seed = SmallStudy(2);
  other_seed.seed = 43;
  EXPECT_NE(TrialsCsv(one), TrialsCsv(RunStudy(other_seed)));
}

TEST(RunStudy, LayoutNoiseFreeExactnessAndSummaries) {
  const StudyOptions options = SmallStudy(2);
  const StudyResult result = RunStudy(options);
  const int methods = 3, trials = 6;
  ASSERT_EQ(result.trials.size(), 3u * trials * methods);
  ASSERT_EQ(result.summaries.size(), 3u * methods);
  for (size_t k = 0; k < result.trials.size(); ++k) {
    const TrialResult& t = result.trials[k];
    EXPECT_EQ(t.setting, static_cast<int>(k / (trials * methods)));
    EXPECT_EQ(t.trial, static_cast<int>(k / methods % trials));
    EXPECT_EQ(t.method, options.methods[k % methods]);
    EXPECT_EQ(t.status, TrialStatus::kOk) << t.message;
    if (t.setting == 0) {
      // Noise-free: every method recovers X.
      EXPECT_LT(t.rotation_error, 1e-9);
      EXPECT_LT(t.translation_error, 1e-9);
    } else {
      EXPECT_GT(t.rotation_error, 1e-6);  // noisy: errors are real
      EXPECT_LT(t.rotation_error, 10.0 * kRadiansPerDegree);
    }
  }
  // Bounds: 0 without noise, positive with.
  EXPECT_EQ(result.setting_bounds[0].rotation, 0.0);
  EXPECT_GT(result.setting_bounds[1].rotation, 0.0);
  EXPECT_GT(result.setting_bounds[2].translation, 0.0);
  // Summary statistics agree with the trials they summarise.
  for (const MethodSummary& s : result.summaries) {
    double sum_sq = 0.0, worst = 0.0;
    for (const TrialResult& t : result.trials) {
      if (t.setting != s.setting || t.method != s.method) continue;
      sum_sq += t.translation_error * t.translation_error;
      worst = std::max(worst, t.rotation_error);
    }
    EXPECT_NEAR(s.translation.rmse, std::sqrt(sum_sq / trials), 1e-15);
    EXPECT_EQ(s.rotation.max, worst);
    EXPECT_EQ(s.trials, trials);
    EXPECT_EQ(s.failures, 0);
  }
}

TEST(RunStudy, NoiseSweepsShareTheGroundTruthPerTrial) {
  // Common random numbers: the same truth and stations per trial, only the noise differs. The
  // first-order bound depends on those and scales linearly with σ, so trial by trial the bound
  // at 2σ is exactly twice the bound at σ — it would not be for different data sets.
  StudyOptions options;
  options.settings = {MakeSetting(handeye::Setup::kEyeInHand, 6, 0.5, 0.5),
                      MakeSetting(handeye::Setup::kEyeInHand, 6, 1.0, 1.0)};
  options.methods = {estimation::Method::kParkMartin};
  options.trials = 4;
  const StudyResult result = RunStudy(options);
  for (int t = 0; t < 4; ++t) {
    EXPECT_NEAR(result.bounds[1][t].rotation, 2.0 * result.bounds[0][t].rotation,
                1e-9 * result.bounds[1][t].rotation);
    EXPECT_NEAR(result.bounds[1][t].translation, 2.0 * result.bounds[0][t].translation,
                1e-9 * result.bounds[1][t].translation);
  }
  EXPECT_NE(result.bounds[0][0].rotation, result.bounds[0][1].rotation);
}

TEST(RunStudy, RoundingNoiseIsNeverAnOutlier) {
  // Noise-free errors are rounding noise spread over decades (1e-16 … 1e-12); the outlier floor
  // keeps the triangle threshold from cutting its upper end.
  StudyOptions options;
  options.settings = {MakeSetting(handeye::Setup::kEyeInHand, 3, 0.0, 0.0),
                      MakeSetting(handeye::Setup::kEyeInHand, 5, 0.0, 0.0)};
  options.methods = {estimation::Method::kParkMartin, estimation::Method::kAndreff};
  options.trials = 60;
  const StudyResult result = RunStudy(options);
  for (const MethodSummary& s : result.summaries) EXPECT_EQ(s.outliers, 0);
}

TEST(StudyCsv, HeaderAndOneRowPerTrialAndMethod) {
  StudyOptions options;
  options.settings = {MakeSetting(handeye::Setup::kEyeToHand, 5, 0.3, 0.3)};
  options.methods = {estimation::Method::kParkMartin, estimation::Method::kTsaiLenz};
  options.trials = 3;
  const StudyResult result = RunStudy(options);
  const std::string trials = TrialsCsv(result);
  EXPECT_EQ(trials.rfind("setup,stations,noise_on,noise,sigma_mm,sigma_deg,trial,method,status,"
                         "rotation_error_deg,translation_error_mm,outlier,",
                         0),
            0u);
  EXPECT_EQ(std::count(trials.begin(), trials.end(), '\n'), 1 + 3 * 2);
  EXPECT_NE(trials.find("\neye-to-hand,5,both,gaussian,0.3,0.3,0,park-martin,ok,"),
            std::string::npos);
  const std::string summary = SummaryCsv(result);
  EXPECT_EQ(std::count(summary.begin(), summary.end(), '\n'), 1 + 2);
  EXPECT_NE(summary.find("\neye-to-hand,5,both,gaussian,0.3,0.3,tsai-lenz,3,0,"),
            std::string::npos);
  EXPECT_EQ(FormatNumber(std::nan("")), "nan");
  EXPECT_EQ(FormatNumber(0.1), "0.1");
  EXPECT_EQ(FormatNumber(1.0 / 3.0), "0.333333333");
}

// The covariance consistency criterion of docs/uncertainty.md on the thesis protocol (n = 15, σ = 1
// mm / 1° on both, 200 trials, the default seed), for ml with its linear covariance in both setups:
// the mean NEES lies in the 95% χ² band for 6 dof × 200 trials, and the 1σ/2σ ellipsoid coverage is
// within 5 points of 68.3/95.4% (the sampling standard deviation of a 200-trial coverage is
// 3.3 / 1.5 points; docs/uncertainty.md reports the exact figures and larger runs).
StudyOptions MlLinearStudy(std::vector<Setting> settings, int trials) {
  StudyOptions options;
  options.settings = std::move(settings);
  options.methods = {estimation::Method::kMl};
  options.trials = trials;
  options.covariance.method = estimation::CovarianceMethod::kLinear;
  return options;
}

TEST(RunStudy, MlLinearCovarianceIsConsistent) {
  const StudyResult result =
      RunStudy(MlLinearStudy({MakeSetting(handeye::Setup::kEyeInHand, 15, 1.0, 1.0),
                              MakeSetting(handeye::Setup::kEyeToHand, 15, 1.0, 1.0)},
                             200));
  ASSERT_EQ(result.summaries.size(), 2u);
  for (const MethodSummary& summary : result.summaries) {
    ASSERT_TRUE(summary.consistency.has_value());
    const uncertainty::Consistency& c = *summary.consistency;
    EXPECT_EQ(c.trials, 200);
    EXPECT_EQ(c.dof, 6);
    EXPECT_TRUE(c.band.Contains(c.mean_nees)) << c.mean_nees;
    EXPECT_NEAR(c.coverage_1sigma, 0.683, 0.05);
    EXPECT_NEAR(c.coverage_2sigma, 0.954, 0.05);
    for (int j = 0; j < 6; ++j) EXPECT_NEAR(c.sd_ratio(j), 1.0, 0.15) << j;
  }
  for (const TrialResult& trial : result.trials) {
    EXPECT_TRUE(std::isfinite(trial.nees));
    ASSERT_TRUE(trial.covariance_X.has_value());
  }
  // With the model right the model check inflates only by chance (2.3% per axis of X, about
  // 13% of the data sets; measured 15% and 13%), and the model-only covariance is consistent.
  for (const MethodSummary& summary : result.summaries) {
    EXPECT_LE(summary.check_used, 40);
    ASSERT_TRUE(summary.consistency_model.has_value());
    EXPECT_TRUE(summary.consistency_model->band.Contains(summary.consistency_model->mean_nees));
  }
  // The CSV files carry the NEES per trial and the consistency per summary row.
  EXPECT_NE(TrialsCsv(result).find(",nees,"), std::string::npos);
  EXPECT_NE(SummaryCsv(result).find("mean_nees,nees_band_low"), std::string::npos);
}

// The noise estimated (no sigmas given) on data that break the isotropic, equally split Gaussian
// noise model, 100 trials each, n = 15. PnP-shaped camera noise (eye-to-hand) and a robot five
// times noisier than the camera (eye-in-hand) are taken by the richer noise models
// (noise_estimation.h), Student-t(3) noise (eye-in-hand) by the heavy-tailed model
// (student_t.h): the model-only covariance is consistent (1σ coverage within 10 points of 68% —
// 100 trials give a binomial sd of 4.7 points — 2σ ≥ 90%, every σ ratio ≥ 0.85) and the check
// rarely needs to inflate (≤ 20 of 100). Student-t with the Gaussian models only covered 56 / 87
// (model only) and needed the check on 25 of 100; now the model alone covers 66 / 92 and the
// check fired 3 times. docs/uncertainty.md has the 200-trial table.
TEST(RunStudy, RicherNoiseModelsCoverWhenTheIsotropicGaussianModelIsWrong) {
  Setting pnp = MakeSetting(handeye::Setup::kEyeToHand, 15, 1.0, 1.0, NoiseOn::kBoth,
                            sim::NoiseModel::Kind::kPnp);
  Setting heavy = MakeSetting(handeye::Setup::kEyeInHand, 15, 1.0, 1.0, NoiseOn::kBoth,
                              sim::NoiseModel::Kind::kStudentT3);
  Setting robot = MakeSetting(handeye::Setup::kEyeInHand, 15, 0.2, 0.2);
  robot.robot_scale = 5.0;
  for (const Setting& setting : {pnp, heavy, robot}) {
    StudyOptions options = MlLinearStudy({setting}, 100);
    options.estimate_noise = true;
    const StudyResult result = RunStudy(options);
    ASSERT_EQ(result.summaries.size(), 1u);
    const MethodSummary& s = result.summaries[0];
    SCOPED_TRACE(std::string(sim::NoiseKindName(setting.noise_kind)) + ", robot x" +
                 std::to_string(setting.robot_scale));
    ASSERT_TRUE(s.consistency && s.consistency_model);
    const uncertainty::Consistency& model = *s.consistency_model;
    EXPECT_NEAR(model.coverage_1sigma, 0.68, 0.10);
    EXPECT_GE(model.coverage_2sigma, 0.90);
    EXPECT_GE(model.sd_ratio.minCoeff(), 0.85);
    EXPECT_LE(s.check_used, 20);
  }
}

// The data set on which the estimated translation noise collapsed (docs/uncertainty.md): trial
// 182 of `hecal simulate --stations 8 --setup eye-in-hand --sigma 0.2 --robot-scale 5
// --estimate-noise --method ml` (seed 1), robot 1 mm / 1°, camera 0.2 mm / 0.2°. The model with
// the camera's tilt/depth excess and the robot's rotation apart was chosen there, its shared
// translation variance resting on ~0 effective degrees of freedom (the depth excess takes the
// same residuals): σ_t 0.062 mm, X's NEES 509. Such a model is no longer eligible
// (noise_estimation.h, "Richer noise models"). Asserted: the translation sigma within a factor
// 5 of the equal-split truth √((1² + 0.2²)/2) = 0.72 mm — the isotropic translation group
// rests on ≈ 2 effective degrees of freedom here, under which a factor 4 low happens in ~6% of
// data sets (χ²₂/2 < 1/16), a factor 5 in ~4%, so no tighter factor is honest (measured: 0.174
// mm, 4.1 low) — and X's NEES under the reported covariance below 100 (measured 72.8; it is
// still far above χ²(6)'s 3σ quantile 20.06: the isotropic translation sigma is itself 4× low
// on this data set, which no rule here corrects — docs/uncertainty.md, "Out of reach").
TEST(RunStudy, TheTranslationNoiseOfTrial182DoesNotCollapse) {
  std::mt19937_64 rng(TrialSeed(1, handeye::Setup::kEyeInHand, 8, 182));
  sim::ProtocolOptions protocol;
  protocol.setup = handeye::Setup::kEyeInHand;
  protocol.stations = 8;
  sim::NoiseModel robot, camera;
  robot.rotation_sigma = kRadiansPerDegree;
  robot.translation_sigma = 1e-3;
  camera.rotation_sigma = 0.2 * kRadiansPerDegree;
  camera.translation_sigma = 0.2e-3;
  const sim::SimulatedData data = sim::SimulateThesisProtocol(protocol, robot, camera, rng);
  estimation::CalibrateOptions options;
  options.covariance.method = estimation::CovarianceMethod::kLinear;
  const estimation::CalibrationResult result =
      estimation::Calibrate(data.MeasuredProblem(), options);
  const double truth = std::sqrt((1.0 + 0.04) / 2.0) * 1e-3;
  EXPECT_GT(result.robot_sigma.translation, truth / 5.0);
  EXPECT_LT(result.robot_sigma.translation, truth * 5.0);
  ASSERT_TRUE(result.covariance.has_value());
  const Matrix6d covariance = result.covariance->covariance.topLeftCorner<6, 6>();
  const double nees = uncertainty::Nees(se3::Log(result.X.inverse() * data.X), covariance);
  EXPECT_LT(nees, 100.0);
}

// The same check catches an optimistic covariance: the study's errors against covariances a
// quarter the size (σ halved) put the mean NEES above its band.
TEST(RunStudy, AnOptimisticCovarianceLeavesTheBand) {
  const StudyResult consistent =
      RunStudy(MlLinearStudy({MakeSetting(handeye::Setup::kEyeInHand, 15, 1.0, 1.0)}, 100));
  std::vector<Eigen::VectorXd> errors;
  std::vector<Eigen::MatrixXd> covariances;
  for (const TrialResult& trial : consistent.trials) {
    errors.emplace_back(trial.error_X);
    covariances.emplace_back(0.25 * *trial.covariance_X);
  }
  const uncertainty::Consistency optimistic = uncertainty::AssessConsistency(errors, covariances);
  EXPECT_GT(optimistic.mean_nees, optimistic.band.high);
  EXPECT_LT(optimistic.coverage_1sigma, 0.4);
}

// Without --covariance nothing changes: no covariance, NaN NEES, no consistency.
TEST(RunStudy, NoCovarianceByDefault) {
  StudyOptions options;
  options.settings = {MakeSetting(handeye::Setup::kEyeInHand, 6, 1.0, 1.0)};
  options.methods = {estimation::Method::kParkMartin};
  options.trials = 3;
  const StudyResult result = RunStudy(options);
  EXPECT_FALSE(result.summaries[0].consistency.has_value());
  EXPECT_TRUE(std::isnan(result.trials[0].nees));
}

}  // namespace
}  // namespace hecal::study

namespace hecal::study {
namespace {

// Gross outliers, the thesis protocol: n = 20, σ = 1 mm / 1° on robot and camera, 200 trials,
// k = 1, 2, 4 stations with a random robot pose, both setups, ml with calibrate's outlier
// rejection. Every outlier is found in ≥ 98% of the trials, ≤ 2% of the good stations are
// rejected, and X's RMSE is within 1.15× that of the same data sets without the outliers
// (measured: 100% found, 0.3–0.6% good rejected, ratio 1.000). Without the rejection the same
// data give RMSEs of degrees to tens of degrees.
TEST(RunStudy, GrossOutliersAreRejectedAndCostNothing) {
  StudyOptions options;
  options.methods = {estimation::Method::kMl};
  options.trials = 200;
  options.reject_outliers = true;
  for (handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    for (int k : {1, 2, 4}) {
      Setting setting = MakeSetting(setup, 20, 1.0, 1.0);
      setting.gross_outliers = k;
      options.settings.push_back(setting);
    }
  }
  const StudyResult result = RunStudy(options);
  for (const MethodSummary& s : result.summaries) {
    const Setting& setting = options.settings[s.setting];
    SCOPED_TRACE(std::string(handeye::SetupName(setting.setup)) +
                 ", k = " + std::to_string(setting.gross_outliers));
    EXPECT_EQ(s.failures, 0);
    EXPECT_GE(s.trials_all_found, 196);  // ≥ 98% of the trials
    EXPECT_GE(s.outliers_rejected, 0.98 * s.outliers_injected);
    EXPECT_LE(s.good_rejected, 0.02 * s.good_stations);
    EXPECT_LE(s.rotation.rmse, 1.15 * s.rotation_rmse_clean);
    EXPECT_LE(s.translation.rmse, 1.15 * s.translation_rmse_clean);
  }
  options.reject_outliers = false;
  options.trials = 20;
  options.settings.resize(1);  // eye-in-hand, k = 1
  const MethodSummary kept = RunStudy(options).summaries.at(0);
  EXPECT_GT(kept.rotation.rmse, 5.0 * kept.rotation_rmse_clean);
  EXPECT_EQ(kept.outliers_rejected, 0);
}

// Too many gross outliers for the stations is refused as an option.
TEST(ValidateStudyOptions, RejectsOutliersThatLeaveTooFewGoodStations) {
  StudyOptions options;
  options.methods = {estimation::Method::kMl};
  Setting setting = MakeSetting(handeye::Setup::kEyeInHand, 5, 1.0, 1.0);
  setting.gross_outliers = 3;
  options.settings = {setting};
  EXPECT_THROW(ValidateStudyOptions(options), InputError);
  options.settings[0].gross_outliers = 2;
  EXPECT_NO_THROW(ValidateStudyOptions(options));
  options.settings[0].gross_outliers = -1;
  EXPECT_THROW(ValidateStudyOptions(options), InputError);
}

}  // namespace
}  // namespace hecal::study
