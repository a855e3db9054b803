// Test support (not installed): the checks every closed-form hand–eye solver must pass,
// shared by the per-solver tests so each test file only names its solver.
//  - NoiseFreeCases: thesis protocol n = 3, 5, 15, 50 and WideRotationCase (170°–179.9°
//    relative rotations; random X, X rotated by exactly π, by 179.999°, X's rotation the
//    identity and 1e-6 rad), both setups; every method runs them in
//    src/estimation/every_method_test.cc.
//  - RunNoisyStudy: seeded thesis-protocol trials with Gaussian noise on robot and camera.
//  - BenignCase: moderate rotations (≤ 80° between stations), the data every peer handles.
//  - ParallelAxesCase / PureTranslationCase: degenerate data (noise-free);
//    ExpectDegenerateDataThrow runs them (and 2 stations) through a solver.
//  - ExpectWithinTabbTolerance: the upstream acceptance on data/tabb-rwhe-dataset1.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "hecal/core/error.h"
#include "hecal/core/random_draws.h"
#include "hecal/geometry/so3.h"
#include "hecal/handeye/motion.h"
#include "hecal/handeye/problem.h"
#include "testing/handeye_cases.h"
#include "testing/tabb_dataset.h"

namespace hecal::testing {

using ProblemSolver = std::function<handeye::Solution(const handeye::Problem&)>;

// A motion-based solver as the dispatcher runs it: X from the station-pair motions (motion.h),
// Z by EstimateZ.
inline ProblemSolver FromMotionSolver(
    const std::function<Pose(const std::vector<handeye::Motion>&)>& solve) {
  return [solve](const handeye::Problem& problem) {
    const Pose X = solve(handeye::StationPairMotions(problem));
    return handeye::Solution{X, handeye::EstimateZ(problem, X)};
  };
}

inline double Degrees(double radians) {
  return radians * 180.0 / std::numbers::pi;
}

struct NamedCase {
  std::string name;
  Scene data;
};

inline std::vector<NamedCase> NoiseFreeCases() {
  constexpr double pi = std::numbers::pi;
  std::vector<NamedCase> cases;
  uint64_t seed = 100;
  for (handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    const std::string setup_name(handeye::SetupName(setup));
    for (int n : {3, 5, 15, 50}) {
      for (int repeat = 0; repeat < 3; ++repeat) {
        cases.push_back(
            {setup_name + " thesis n=" + std::to_string(n) + " seed " + std::to_string(seed),
             ThesisCase(setup, n, seed)});
        ++seed;
      }
    }
    for (int n : {3, 6, 12}) {
      cases.push_back(
          {setup_name + " wide n=" + std::to_string(n), WideRotationCase(setup, n, seed++)});
      cases.push_back({setup_name + " wide n=" + std::to_string(n) + " X angle pi",
                       WideRotationCase(setup, n, seed++, pi)});
      cases.push_back({setup_name + " wide n=" + std::to_string(n) + " X angle 179.999 deg",
                       WideRotationCase(setup, n, seed++, pi - 1e-3 * pi / 180.0)});
      cases.push_back({setup_name + " wide n=" + std::to_string(n) + " X angle 0",
                       WideRotationCase(setup, n, seed++, 0.0)});
      cases.push_back({setup_name + " wide n=" + std::to_string(n) + " X angle 1e-6 rad",
                       WideRotationCase(setup, n, seed++, 1e-6)});
    }
  }
  return cases;
}

// Rotation (rad) and translation (m) errors both within `tolerance`.
inline void ExpectPoseNear(const Pose& estimate, const Pose& truth, double tolerance,
                           const std::string& what) {
  const PoseError error = Error(estimate, truth);
  EXPECT_LE(error.rotation, tolerance) << what << " rotation";
  EXPECT_LE(error.translation, tolerance) << what << " translation";
}

struct NoisyStudy {
  int trials = 0;
  double worst_rotation_deg = 0.0;     // X
  double worst_translation_m = 0.0;    // X
  double median_rotation_deg = 0.0;    // X
  double worst_z_rotation_deg = 0.0;   // Z
  double worst_z_translation_m = 0.0;  // Z
};

// `trials` seeded data sets: thesis protocol, σ = 0.3 mm / 0.3° Gaussian per component on robot
// AND camera, n cycling through 5, 6, 8, 10, 15, setups alternating.
inline NoisyStudy RunNoisyStudy(const ProblemSolver& solve, int trials, uint64_t seed) {
  constexpr double kSigmaRotation = 0.3 * std::numbers::pi / 180.0;
  constexpr double kSigmaTranslation = 0.3e-3;
  constexpr int kStations[] = {5, 6, 8, 10, 15};
  NoisyStudy study;
  std::vector<double> rotations;
  for (int trial = 0; trial < trials; ++trial) {
    const handeye::Setup setup =
        trial % 2 == 0 ? handeye::Setup::kEyeInHand : handeye::Setup::kEyeToHand;
    const Scene data =
        ThesisCase(setup, kStations[trial % 5], seed + trial, kSigmaRotation, kSigmaTranslation);
    const handeye::Solution solution = solve(data.MeasuredProblem());
    const PoseError x = Error(solution.X, data.X);
    const PoseError z = Error(solution.Z, data.Z);
    rotations.push_back(Degrees(x.rotation));
    study.worst_rotation_deg = std::max(study.worst_rotation_deg, Degrees(x.rotation));
    study.worst_translation_m = std::max(study.worst_translation_m, x.translation);
    study.worst_z_rotation_deg = std::max(study.worst_z_rotation_deg, Degrees(z.rotation));
    study.worst_z_translation_m = std::max(study.worst_z_translation_m, z.translation);
    ++study.trials;
  }
  std::nth_element(rotations.begin(), rotations.begin() + trials / 2, rotations.end());
  study.median_rotation_deg = rotations[trials / 2];
  std::printf(
      "noisy (%d trials, 0.3 mm / 0.3 deg): X rotation median %.3f deg, worst %.3f deg; "
      "X translation worst %.2f mm; Z worst %.3f deg / %.2f mm\n",
      study.trials, study.median_rotation_deg, study.worst_rotation_deg,
      1e3 * study.worst_translation_m, study.worst_z_rotation_deg,
      1e3 * study.worst_z_translation_m);
  return study;
}

// Noise-free data from given camera poses T_target_camera_i and a random X, Z.
inline Scene CaseFromCameraPoses(handeye::Setup setup, const std::vector<Pose>& T_target_camera,
                                 std::mt19937_64& rng) {
  Scene data;
  data.setup = setup;
  data.X = RandomPose(rng, 0.1);
  data.Z = RandomPose(rng, 1.0);
  for (const Pose& T : T_target_camera) {
    const Pose A = data.Z * T * data.X.inverse();
    data.T_base_gripper_true.push_back(setup == handeye::Setup::kEyeInHand ? A : A.inverse());
    data.T_camera_target_true.push_back(T.inverse());
  }
  data.T_base_gripper = data.T_base_gripper_true;
  data.T_camera_target = data.T_camera_target_true;
  return data;
}

// Camera orientations within 40° of a common one (so relative rotations stay below 80°, away
// from π), positions in a 1 m box 1 m from the target; Gaussian noise on robot and camera.
inline Scene BenignCase(handeye::Setup setup, int stations, uint64_t seed,
                        double rotation_sigma = 0.0, double translation_sigma = 0.0) {
  std::mt19937_64 rng(seed);
  const Eigen::Matrix3d R0 = RandomRotation(rng);
  hecal::UniformRealDistribution angle(0.0, 40.0 * std::numbers::pi / 180.0);
  std::vector<Pose> poses;
  for (int i = 0; i < stations; ++i) {
    const Eigen::Matrix3d R = R0 * so3::Exp(RandomRotationVector(rng, angle(rng)));
    poses.push_back(
        MakePose(R, R * Eigen::Vector3d(0.0, 0.0, -1.0) + RandomPose(rng, 0.5).translation()));
  }
  Scene data = CaseFromCameraPoses(setup, poses, rng);
  const PoseNoise noise{rotation_sigma, translation_sigma};
  for (size_t i = 0; i < poses.size(); ++i) {
    data.T_base_gripper[i] = AddPoseNoise(data.T_base_gripper[i], noise, rng);
    data.T_camera_target[i] = AddPoseNoise(data.T_camera_target[i], noise, rng);
  }
  return data;
}

// Every station rotated about the same axis (so every relative rotation axis is parallel).
inline Scene ParallelAxesCase(handeye::Setup setup, int stations, uint64_t seed) {
  std::mt19937_64 rng(seed);
  const Eigen::Matrix3d R0 = RandomRotation(rng);
  const Eigen::Vector3d axis = RandomUnitVector(rng);
  hecal::UniformRealDistribution angle(-std::numbers::pi, std::numbers::pi);
  std::vector<Pose> poses;
  for (int i = 0; i < stations; ++i) {
    const Eigen::Vector3d t = RandomPose(rng, 0.5).translation();  // drawn before the angle
    const double theta = angle(rng);
    poses.push_back(MakePose(R0 * so3::Exp(theta * axis), t));
  }
  return CaseFromCameraPoses(setup, poses, rng);
}

// Every station with the same orientation.
inline Scene PureTranslationCase(handeye::Setup setup, int stations, uint64_t seed) {
  std::mt19937_64 rng(seed);
  const Eigen::Matrix3d R0 = RandomRotation(rng);
  std::vector<Pose> poses;
  for (int i = 0; i < stations; ++i) poses.push_back(MakePose(R0, RandomPose(rng).translation()));
  return CaseFromCameraPoses(setup, poses, rng);
}

// Parallel rotation axes, pure translations and 2 stations, both setups: DegenerateError.
inline void ExpectDegenerateDataThrow(const ProblemSolver& solve) {
  for (handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    SCOPED_TRACE(handeye::SetupName(setup));
    EXPECT_THROW(solve(ParallelAxesCase(setup, 6, 1).MeasuredProblem()), DegenerateError);
    EXPECT_THROW(solve(PureTranslationCase(setup, 6, 2).MeasuredProblem()), DegenerateError);
    EXPECT_THROW(solve(ThesisCase(setup, 2, 3).MeasuredProblem()), DegenerateError);
  }
}

// Upstream acceptance on the real data set (OpenCV's regression test, SOURCE.md): X and Z within
// 1° and 50 mm of Tabb's reference.
inline void ExpectWithinTabbTolerance(const ProblemSolver& solve, const char* name) {
  const TabbDataset tabb = LoadTabbDataset();
  const handeye::Solution solution = solve(
      handeye::MakeProblem(handeye::Setup::kEyeInHand, tabb.T_base_gripper, tabb.T_camera_target));
  const PoseError x = Error(solution.X, tabb.X);
  const PoseError z = Error(solution.Z, tabb.Z);
  std::printf("tabb-rwhe-dataset1 %s vs Tabb: X %.3f deg / %.1f mm, Z %.3f deg / %.1f mm\n", name,
              Degrees(x.rotation), 1e3 * x.translation, Degrees(z.rotation), 1e3 * z.translation);
  EXPECT_LT(Degrees(x.rotation), 1.0);
  EXPECT_LT(x.translation, 0.050);
  EXPECT_LT(Degrees(z.rotation), 1.0);
  EXPECT_LT(z.translation, 0.050);
}

}  // namespace hecal::testing
