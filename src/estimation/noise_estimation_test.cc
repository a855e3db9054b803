#include "hecal/estimation/noise_estimation.h"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "hecal/core/error.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/geometry/se3.h"
#include "hecal/sim/thesis_protocol.h"
#include "testing/handeye_cases.h"
#include "testing/options_validity.h"

namespace hecal::estimation {
namespace {

sim::SimulatedData Simulate(handeye::Setup setup, int stations, const PoseSigma& robot,
                            const PoseSigma& camera, uint64_t seed) {
  std::mt19937_64 rng(seed);
  sim::ProtocolOptions options;
  options.setup = setup;
  options.stations = stations;
  return sim::SimulateThesisProtocol(
      options, {sim::NoiseModel::Kind::kGaussian, robot.rotation, robot.translation},
      {sim::NoiseModel::Kind::kGaussian, camera.rotation, camera.translation}, rng);
}

TEST(ThreeSigmaChiSquare, MatchesTheNormalTail) {
  // χ²(1) at the 3σ level is 3² exactly; χ²(2) has the closed form −2 ln(0.0027).
  EXPECT_NEAR(ThreeSigmaChiSquare(1), 9.0, 1e-9);
  EXPECT_NEAR(ThreeSigmaChiSquare(2), -2.0 * std::log(std::erfc(3.0 / std::sqrt(2.0))), 1e-8);
  EXPECT_NEAR(ThreeSigmaChiSquare(6), 20.062, 1e-3);
}

TEST(NoiseSpec, FollowsTheGivenSigmas) {
  const PoseSigma robot{0.01, 0.001};
  const PoseSigma camera{0.02, 0.002};
  EXPECT_FALSE(NoiseSpec::FromSigmas(robot, camera).AnyEstimated());
  const NoiseSpec none = NoiseSpec::FromSigmas(std::nullopt, std::nullopt);
  EXPECT_EQ(none.NumGroups(), 2);
  EXPECT_EQ(none.group[kRobotRotation], none.group[kCameraRotation]);
  EXPECT_EQ(none.group[kRobotTranslation], none.group[kCameraTranslation]);
  EXPECT_NE(none.group[kRobotRotation], none.group[kRobotTranslation]);
  const NoiseSpec robot_known = NoiseSpec::FromSigmas(robot, std::nullopt);
  EXPECT_LT(robot_known.group[kRobotRotation], 0);
  EXPECT_DOUBLE_EQ(robot_known.variances[kRobotRotation], 1e-4);
  EXPECT_GE(robot_known.group[kCameraTranslation], 0);
}

// The σ scale is recovered from the residuals: equal robot and camera noise (the estimator's
// split), many stations so that the sampling error of the estimate is small. With n stations
// the translation scale rests on ≈ 2n effective degrees of freedom here (most of the translation
// residual is robot rotation noise times the lever arm), so n = 400 gives a relative standard
// error ≈ 1/√(2·2n) ≈ 2.5% on σ_t, ~1% on σ_r; 7% is > 2.5σ for σ_t.
TEST(EstimateNoise, RecoversTheSigmaScaleBothSetups) {
  for (handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    const PoseSigma sigma{1.0 * kRadiansPerDegree, 1e-3};
    const sim::SimulatedData data = Simulate(setup, 400, sigma, sigma, 21);
    const handeye::Problem problem = data.MeasuredProblem();
    const NoiseEstimate estimate = EstimateNoise(LinearizeStations(problem, data.X, data.Z),
                                                 NoiseSpec::FromSigmas(std::nullopt, std::nullopt),
                                                 handeye::LengthScale(problem));
    EXPECT_TRUE(estimate.converged);
    EXPECT_NEAR(estimate.robot().rotation / sigma.rotation, 1.0, 0.03);
    EXPECT_NEAR(estimate.robot().translation / sigma.translation, 1.0, 0.07);
    EXPECT_DOUBLE_EQ(estimate.robot().rotation, estimate.camera().rotation);
    int flagged = 0;
    for (const StationTest& test : estimate.stations) flagged += test.outlier ? 1 : 0;
    EXPECT_LE(flagged, 6);  // expected 400 · 0.0027 ≈ 1
  }
}

// With the robot noise given, the camera's own rotation and translation sigmas are estimated.
TEST(EstimateNoise, EstimatesTheCameraGivenTheRobot) {
  const PoseSigma robot{0.2 * kRadiansPerDegree, 0.5e-3};
  const PoseSigma camera{1.0 * kRadiansPerDegree, 3e-3};
  const sim::SimulatedData data = Simulate(handeye::Setup::kEyeInHand, 300, robot, camera, 22);
  const handeye::Problem problem = data.MeasuredProblem();
  const NoiseEstimate estimate =
      EstimateNoise(LinearizeStations(problem, data.X, data.Z),
                    NoiseSpec::FromSigmas(robot, std::nullopt), handeye::LengthScale(problem));
  EXPECT_DOUBLE_EQ(estimate.robot().rotation, robot.rotation);
  EXPECT_NEAR(estimate.camera().rotation / camera.rotation, 1.0, 0.06);
  EXPECT_NEAR(estimate.camera().translation / camera.translation, 1.0, 0.08);
}

// Linearised anywhere near the optimum (here: a perturbed truth) the linear re-fit inside the
// estimator removes the offset, so the estimate does not depend on the exact point.
TEST(EstimateNoise, IndependentOfTheLinearisationPointNearTheOptimum) {
  const PoseSigma sigma{0.5 * kRadiansPerDegree, 2e-3};
  const sim::SimulatedData data = Simulate(handeye::Setup::kEyeToHand, 60, sigma, sigma, 23);
  const handeye::Problem problem = data.MeasuredProblem();
  const NoiseSpec spec = NoiseSpec::FromSigmas(std::nullopt, std::nullopt);
  const double L = handeye::LengthScale(problem);
  Vector6d offset;
  offset << 0.002, -0.001, 0.001, 0.003, 0.001, -0.002;
  const NoiseEstimate at_truth = EstimateNoise(LinearizeStations(problem, data.X, data.Z), spec, L);
  const NoiseEstimate nearby = EstimateNoise(
      LinearizeStations(problem, data.X * se3::Exp(offset), data.Z * se3::Exp(-offset)), spec, L);
  EXPECT_NEAR(nearby.robot().rotation / at_truth.robot().rotation, 1.0, 0.01);
  EXPECT_NEAR(nearby.robot().translation / at_truth.robot().translation, 1.0, 0.02);
}

// One corrupted station is flagged, the others are not, and it does not inflate the sigmas.
TEST(EstimateNoise, FlagsACorruptedStationWithoutBeingMaskedByIt) {
  const PoseSigma sigma{1.0 * kRadiansPerDegree, 1e-3};
  sim::SimulatedData data = Simulate(handeye::Setup::kEyeInHand, 15, sigma, sigma, 24);
  const sim::SimulatedData clean = data;
  Vector6d gross;
  gross << 0.0, 8.0 * kRadiansPerDegree, 0.0, 0.0, 0.0, 0.0;
  data.T_camera_target[6] = data.T_camera_target[6] * se3::Exp(gross);
  const NoiseSpec spec = NoiseSpec::FromSigmas(std::nullopt, std::nullopt);
  const handeye::Problem problem = data.MeasuredProblem();
  const NoiseEstimate estimate = EstimateNoise(LinearizeStations(problem, data.X, data.Z), spec,
                                               handeye::LengthScale(problem));
  for (int i = 0; i < 15; ++i) EXPECT_EQ(estimate.stations[i].outlier, i == 6) << "station " << i;
  const handeye::Problem clean_problem = clean.MeasuredProblem();
  const NoiseEstimate reference = EstimateNoise(LinearizeStations(clean_problem, clean.X, clean.Z),
                                                spec, handeye::LengthScale(clean_problem));
  // Excluding the flagged station, the sigma stays near the clean data's estimate (14 vs 15
  // stations), instead of being inflated by the 8° error.
  EXPECT_NEAR(estimate.robot().rotation / reference.robot().rotation, 1.0, 0.15);
}

TEST(EstimateNoise, GivenSigmasAreUsedAsIsAndTooSmallOnesFlagEverything) {
  const PoseSigma sigma{1.0 * kRadiansPerDegree, 1e-3};
  const sim::SimulatedData data = Simulate(handeye::Setup::kEyeInHand, 15, sigma, sigma, 25);
  const handeye::Problem problem = data.MeasuredProblem();
  const PoseSigma small{0.05 * kRadiansPerDegree, 0.05e-3};
  const NoiseEstimate estimate =
      EstimateNoise(LinearizeStations(problem, data.X, data.Z), NoiseSpec::FromSigmas(small, small),
                    handeye::LengthScale(problem));
  EXPECT_EQ(estimate.iterations, 0);
  EXPECT_DOUBLE_EQ(estimate.robot().rotation, small.rotation);
  int flagged = 0;
  for (const StationTest& test : estimate.stations) flagged += test.outlier ? 1 : 0;
  EXPECT_GE(flagged, 13);
}

// Eight eye-in-hand stations, equal 1 mm / 1° noise: the translation variance rests on a few
// effective degrees of freedom (the translation residuals are mostly robot rotation noise times
// the lever arms), and its REML point estimate falls to a small fraction of the truth in some data
// sets. The posterior mean cannot: below 0.35 σ_t (an eighth of the variance) in none of 40 sets,
// while REML is (the first assertion shows that the case is the hard one). The posterior errs
// upward — the data cannot bound σ_t from above either (measured RMS ratio 1.66 over the 40
// sets) — but not wildly: RMS ratio within 0.8–2.
TEST(EstimateNoise, PosteriorMeanDoesNotCollapseWithEightStations) {
  const PoseSigma sigma{1.0 * kRadiansPerDegree, 1e-3};
  int reml_collapsed = 0, posterior_collapsed = 0;
  double sum_ratio2 = 0.0;
  const int sets = 40;
  for (int set = 0; set < sets; ++set) {
    const sim::SimulatedData data =
        Simulate(handeye::Setup::kEyeInHand, 8, sigma, sigma, 500 + set);
    const handeye::Problem problem = data.MeasuredProblem();
    const NoiseEstimate estimate = EstimateNoise(LinearizeStations(problem, data.X, data.Z),
                                                 NoiseSpec::FromSigmas(std::nullopt, std::nullopt),
                                                 handeye::LengthScale(problem));
    const double reml = std::sqrt(estimate.reml_variances[kRobotTranslation]) / sigma.translation;
    const double posterior = estimate.robot().translation / sigma.translation;
    reml_collapsed += reml < 0.35 ? 1 : 0;
    posterior_collapsed += posterior < 0.35 ? 1 : 0;
    sum_ratio2 += posterior * posterior;
    // Never below the REML point (the grid reaches beyond it on both sides).
    EXPECT_GE(posterior, 0.9 * reml);
  }
  EXPECT_GE(reml_collapsed, 2);
  EXPECT_EQ(posterior_collapsed, 0);
  const double rms = std::sqrt(sum_ratio2 / sets);
  EXPECT_GT(rms, 0.8);
  EXPECT_LT(rms, 2.0);
}

// With many stations the likelihood is sharp and the posterior mean σ² is the REML point times
// ≈ 1 + 2.9/ν ≈ 1.01 (ν ≈ 3n − 6 rotation degrees of freedom at n = 100).
TEST(EstimateNoise, PosteriorMeanIsTheRemlPointWhenWellDetermined) {
  const PoseSigma sigma{1.0 * kRadiansPerDegree, 1e-3};
  for (handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    const sim::SimulatedData data = Simulate(setup, 100, sigma, sigma, 77);
    const handeye::Problem problem = data.MeasuredProblem();
    const NoiseEstimate estimate = EstimateNoise(LinearizeStations(problem, data.X, data.Z),
                                                 NoiseSpec::FromSigmas(std::nullopt, std::nullopt),
                                                 handeye::LengthScale(problem));
    const double ratio =
        estimate.variances[kRobotRotation] / estimate.reml_variances[kRobotRotation];
    EXPECT_GT(ratio, 1.0);
    EXPECT_LT(ratio, 1.05);
  }
}

TEST(EstimateNoise, NoiseFreeDataGiveTinyPositiveSigmas) {
  const testing::Scene data = testing::ThesisCase(handeye::Setup::kEyeToHand, 8, 26);
  const handeye::Problem problem = data.MeasuredProblem();
  const NoiseEstimate estimate = EstimateNoise(LinearizeStations(problem, data.X, data.Z),
                                               NoiseSpec::FromSigmas(std::nullopt, std::nullopt),
                                               handeye::LengthScale(problem));
  EXPECT_GT(estimate.robot().rotation, 0.0);
  EXPECT_LT(estimate.robot().rotation, 1e-9);
  EXPECT_GT(estimate.robot().translation, 0.0);
  EXPECT_LT(estimate.robot().translation, 1e-9);
}

// The estimate on `stations` stations of PnP-shaped camera noise (robot noise 0.05° / 0.05 mm,
// given; camera σ 1° / 1 mm shaped as sim::NoiseModel::Kind::kPnp), and its check against the
// truth's parts (below) to a relative `tolerance` (the isotropic rotation, the spin, to
// `spin_tolerance`: it rests on fewer degrees of freedom).
NoiseEstimate EstimatePnpShapedCameraNoise(int stations, uint64_t seed) {
  const PoseSigma robot{0.05 * kRadiansPerDegree, 0.05e-3};
  std::mt19937_64 rng(seed);
  sim::ProtocolOptions options;
  options.setup = handeye::Setup::kEyeInHand;
  options.stations = stations;
  const sim::SimulatedData data = sim::SimulateThesisProtocol(
      options, {sim::NoiseModel::Kind::kGaussian, robot.rotation, robot.translation},
      {sim::NoiseModel::Kind::kPnp, 1.0 * kRadiansPerDegree, 1e-3}, rng);
  const handeye::Problem problem = data.MeasuredProblem();
  return EstimateNoise(LinearizeStations(problem, data.X, data.Z),
                       NoiseSpec::FromSigmas(robot, std::nullopt), handeye::LengthScale(problem));
}

void ExpectPnpShapedCameraParts(const NoiseEstimate& estimate, double spin_tolerance,
                                double tolerance) {
  EXPECT_TRUE(estimate.richer);
  EXPECT_NEAR(estimate.camera().rotation / (0.1 * kRadiansPerDegree), 1.0, spin_tolerance);
  EXPECT_NEAR(estimate.camera().translation / 0.5e-3, 1.0, tolerance);
  EXPECT_NEAR(estimate.camera_excess().rotation / (std::sqrt(4.0 - 0.01) * kRadiansPerDegree), 1.0,
              tolerance);
  EXPECT_NEAR(estimate.camera_excess().translation / (std::sqrt(25.0 - 0.25) * 1e-3), 1.0,
              tolerance);
}

// PnP-shaped camera noise (sim/noise.h: tilt 2σ, spin 0.1σ, lateral 0.5σ, depth 5σ in the camera
// frame) with the robot noise given: the isotropic model cannot take that shape, the likelihood
// ratio chooses the anisotropic one, and its parts are the truth's: isotropic rotation = the spin
// (0.1°), isotropic translation = the lateral σ (0.5 mm), tilt excess √(2² − 0.1²)° and depth
// excess √(5² − 0.5²) mm. n = 300: each σ to a few percent (≥ 150 degrees of freedom each).
TEST(EstimateNoise, ChoosesTheAnisotropicCameraModelForPnpShapedNoise) {
  const NoiseEstimate estimate = EstimatePnpShapedCameraNoise(300, 25);
  EXPECT_GT(estimate.likelihood_ratio, 5.991);
  ExpectPnpShapedCameraParts(estimate, 0.15, 0.1);
}

// Isotropic noise: the richer model gains little likelihood and is not chosen (the test's level
// is about 2%, so a chance choice is possible on other data; these are fixed), and with the
// camera noise given it is not tried at all.
TEST(EstimateNoise, KeepsTheIsotropicModelForIsotropicNoise) {
  const PoseSigma sigma{1.0 * kRadiansPerDegree, 1e-3};
  for (handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    const sim::SimulatedData data = Simulate(setup, 40, sigma, sigma, 26);
    const handeye::Problem problem = data.MeasuredProblem();
    const std::vector<StationLinearization> stations = LinearizeStations(problem, data.X, data.Z);
    const double L = handeye::LengthScale(problem);
    const NoiseEstimate estimate =
        EstimateNoise(stations, NoiseSpec::FromSigmas(std::nullopt, std::nullopt), L);
    EXPECT_FALSE(estimate.richer);
    EXPECT_LT(estimate.likelihood_ratio, 5.991);
    EXPECT_EQ(estimate.camera_excess().rotation, 0.0);
    EXPECT_EQ(estimate.camera_excess().translation, 0.0);
    const NoiseEstimate given =
        EstimateNoise(stations, NoiseSpec::FromSigmas(std::nullopt, sigma), L);
    EXPECT_FALSE(given.richer);
    EXPECT_EQ(given.likelihood_ratio, 0.0);
  }
}

// Robot rotation noise 5× the camera's, eye-in-hand, neither given: the robot's rotation error
// shows in the translation residuals through the lever arm, the camera's does not, so the two
// rotation variances are told apart and the richer model is chosen (the equal split would put
// 0.72° on each). n = 60: each rotation σ to about 10%.
TEST(EstimateNoise, TellsUnequalRobotAndCameraRotationNoiseApart) {
  const PoseSigma robot{1.0 * kRadiansPerDegree, 1e-3};
  const PoseSigma camera{0.2 * kRadiansPerDegree, 0.2e-3};
  const sim::SimulatedData data = Simulate(handeye::Setup::kEyeInHand, 60, robot, camera, 27);
  const handeye::Problem problem = data.MeasuredProblem();
  const NoiseEstimate estimate = EstimateNoise(LinearizeStations(problem, data.X, data.Z),
                                               NoiseSpec::FromSigmas(std::nullopt, std::nullopt),
                                               handeye::LengthScale(problem));
  EXPECT_TRUE(estimate.richer);
  EXPECT_GT(estimate.likelihood_ratio, 3.841);
  EXPECT_NEAR(estimate.robot().rotation / robot.rotation, 1.0, 0.15);
  EXPECT_NEAR(estimate.camera().rotation / camera.rotation, 1.0, 0.3);
}

// Above kModelChoiceStations the model is chosen on an evenly spread subsample and fitted on
// all stations: PnP-shaped camera noise (as above) on 3000 stations still gets the anisotropic
// model, with each part within a few percent of the truth (≥ 1500 degrees of freedom each).
TEST(EstimateNoise, ChoosesTheModelOnASubsampleAboveTheChoiceSize) {
  ASSERT_GT(size_t{3000}, kModelChoiceStations);
  const NoiseEstimate estimate = EstimatePnpShapedCameraNoise(3000, 28);
  EXPECT_TRUE(estimate.converged);
  ExpectPnpShapedCameraParts(estimate, 0.05, 0.05);
}

// A noise model whose variances cannot make the station covariances positive definite (here no
// component reaches the translation residuals at all: Σ_i has rank 3) is degenerate data, reported
// as DegenerateError naming the noise model, not an internal error.
TEST(EstimateNoise, SingularStationCovarianceIsDegenerate) {
  const PoseSigma sigma{1.0 * kRadiansPerDegree, 1e-3};
  const sim::SimulatedData data = Simulate(handeye::Setup::kEyeInHand, 20, sigma, sigma, 29);
  const handeye::Problem problem = data.MeasuredProblem();
  std::vector<StationLinearization> stations = LinearizeStations(problem, data.X, data.Z);
  for (StationLinearization& station : stations) {
    for (Matrix6d& component : station.components) {
      component.bottomRows<3>().setZero();
      component.rightCols<3>().setZero();
    }
  }
  try {
    EstimateNoise(stations, NoiseSpec::FromSigmas(std::nullopt, std::nullopt),
                  handeye::LengthScale(problem));
    ADD_FAILURE() << "a rank-3 station covariance was accepted";
  } catch (const DegenerateError& error) {
    EXPECT_NE(std::string(error.what()).find("station noise model"), std::string::npos)
        << error.what();
  }
}

// Extremely anisotropic residuals: 5° of rotation noise and 10⁻⁹ m of translation noise (the
// translation group's variance sits at the floor, 10⁻¹² of the rotation one in metres), camera
// poses paired with the wrong robot poses (a wrong target: residuals of the size of the motion).
// The richer models' trial and grid points near singular station covariances are infeasible
// points, not errors: the estimate is finite and positive, or the data are reported degenerate.
TEST(EstimateNoise, NearSingularTrialVariancesAreNotAnInternalError) {
  const PoseSigma sigma{5.0 * kRadiansPerDegree, 1e-9};
  for (int shuffle = 0; shuffle < 2; ++shuffle) {
    const sim::SimulatedData data = Simulate(handeye::Setup::kEyeInHand, 12, sigma, sigma, 30);
    handeye::Problem problem = data.MeasuredProblem();
    if (shuffle == 1) std::rotate(problem.B.begin(), problem.B.begin() + 5, problem.B.end());
    try {
      const NoiseEstimate estimate = EstimateNoise(
          LinearizeStations(problem, data.X, data.Z),
          NoiseSpec::FromSigmas(std::nullopt, std::nullopt), handeye::LengthScale(problem));
      for (double variance : estimate.variances) {
        EXPECT_TRUE(std::isfinite(variance));
        EXPECT_GE(variance, 0.0);
      }
      EXPECT_GT(estimate.robot().rotation, 0.0);
      EXPECT_GT(estimate.robot().translation, 0.0);
    } catch (const DegenerateError&) {
      SUCCEED() << "reported as degenerate data";
    }
  }
}

// T_i against its definition (header, "Outlier test"), computed here with general dense algebra:
// r̂_i = r_i − J_i δ with δ = N⁻¹ Σ J_jᵀ Σ_j⁻¹ r_j over the included stations, C_i = Σ_i ∓ J_i N⁻¹
// J_iᵀ (− included, + left out), T_i = r̂_iᵀ C_i⁺ r̂_i with the pseudo-inverse taken in the metric of
// Σ_i (eigenvalues ≤ 1e-9 of the whitened C_i dropped; their count is T_i's degrees of freedom).
// At n = 4 the 12 unknowns leave the included stations' C_i singular (fewer than 6 degrees of
// freedom); at n = 20 it has full rank. One station is left out in each.
TEST(TestStations, StatisticIsTheWhitenedPseudoInverseForm) {
  const PoseSigma sigma{1.0 * kRadiansPerDegree, 1e-3};
  for (int n : {4, 20}) {
    const sim::SimulatedData data = Simulate(handeye::Setup::kEyeInHand, n, sigma, sigma, 77);
    const std::vector<StationLinearization> stations =
        LinearizeStations(data.MeasuredProblem(), data.X, data.Z);
    std::vector<bool> included(n, true);
    included[1] = false;
    const NoiseVariances theta = NoiseSpec::FromSigmas(sigma, sigma).variances;
    const std::vector<StationTest> tests = TestStations(stations, included, theta);

    Eigen::MatrixXd N = Eigen::MatrixXd::Zero(12, 12);
    Eigen::VectorXd b = Eigen::VectorXd::Zero(12);
    for (int i = 0; i < n; ++i) {
      if (!included[i]) continue;
      const Eigen::MatrixXd J = stations[i].jacobian;
      const Eigen::MatrixXd W = CombineComponents(stations[i].components, theta).inverse();
      N += J.transpose() * W * J;
      b += J.transpose() * W * stations[i].residual;
    }
    const Eigen::MatrixXd N_inverse = N.inverse();
    const Eigen::VectorXd delta = N_inverse * b;
    int fewer_dof = 0;
    for (int i = 0; i < n; ++i) {
      const Eigen::MatrixXd J = stations[i].jacobian;
      const Eigen::MatrixXd S = CombineComponents(stations[i].components, theta);
      const Eigen::MatrixXd C = included[i] ? Eigen::MatrixXd(S - J * N_inverse * J.transpose())
                                            : Eigen::MatrixXd(S + J * N_inverse * J.transpose());
      const Eigen::VectorXd r_hat = stations[i].residual - J * delta;
      const Eigen::MatrixXd L = Eigen::LLT<Eigen::MatrixXd>(S).matrixL();
      const Eigen::MatrixXd C_white = L.triangularView<Eigen::Lower>().solve(
          L.triangularView<Eigen::Lower>().solve(C).transpose());
      const Eigen::VectorXd r_white = L.triangularView<Eigen::Lower>().solve(r_hat);
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(0.5 *
                                                                 (C_white + C_white.transpose()));
      double statistic = 0.0;
      int dof = 0;
      for (int k = 0; k < 6; ++k) {
        if (eigen.eigenvalues()(k) <= 1e-9) continue;
        const double projection = eigen.eigenvectors().col(k).dot(r_white);
        statistic += projection * projection / eigen.eigenvalues()(k);
        ++dof;
      }
      EXPECT_EQ(tests[i].dof, dof) << "n " << n << ", station " << i;
      EXPECT_NEAR(tests[i].statistic, statistic, 1e-6 * (1.0 + statistic))
          << "n " << n << ", station " << i;
      if (dof < 6) ++fewer_dof;
    }
    if (n == 4) {
      EXPECT_GT(fewer_dof, 0) << "the singular case was not exercised";
    } else {
      EXPECT_EQ(fewer_dof, 0);
    }
  }
}

TEST(StationTestOptions, IsValidNamesTheField) {
  const StationTestOptions defaults;
  EXPECT_TRUE(testing::IsValidOptions(defaults));
  EXPECT_TRUE(testing::RefusesNaming(defaults, "StationTestOptions.false_alarm",
                                     [](auto& o) { o.false_alarm = 0.0; }));
  EXPECT_TRUE(testing::RefusesNaming(defaults, "StationTestOptions.false_alarm",
                                     [](auto& o) { o.false_alarm = 1.0; }));
}

}  // namespace
}  // namespace hecal::estimation
