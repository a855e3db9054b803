// The checks every rotation-then-translation solver must pass, run on each of them:
// Tsai–Lenz, Park–Martin, Horaud–Dornaika (R then t), Chou–Kamel, Shiu–Ahmad. Solver-specific
// behaviour is tested in each solver's own <name>_test.cc; the properties of every method
// (noise-free recovery, base-frame invariance, degenerate data) in
// src/estimation/every_method_test.cc.
#include <gtest/gtest.h>

#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "hecal/core/error.h"
#include "hecal/geometry/so3.h"
#include "hecal/handeye/chou_kamel.h"
#include "hecal/handeye/horaud.h"
#include "hecal/handeye/park_martin.h"
#include "hecal/handeye/shiu_ahmad.h"
#include "hecal/handeye/tsai_lenz.h"
#include "testing/handeye_solver_suite.h"

namespace hecal::handeye {
namespace {

struct Solver {
  const char* name;
  Pose (*solve)(const std::vector<Motion>&);
  uint64_t seed;  // of this solver's noisy study (distinct data per solver)
};

const Solver kSolvers[] = {
    {"TsaiLenz", SolveTsaiLenz, 7000},   {"ParkMartin", SolveParkMartin, 7200},
    {"Horaud", SolveHoraud, 7400},       {"ChouKamel", SolveChouKamel, 7600},
    {"ShiuAhmad", SolveShiuAhmad, 7800},
};

class RotationThenTranslation : public ::testing::TestWithParam<Solver> {
 protected:
  testing::ProblemSolver ProblemSolver() const {
    return testing::FromMotionSolver(GetParam().solve);
  }
};

// Two motions with non-parallel axes are the minimum; X is a half-turn about a random axis.
TEST_P(RotationThenTranslation, ExactFromTwoMotionsWithHalfTurnX) {
  std::mt19937_64 rng(GetParam().seed);
  Pose X = testing::RandomPose(rng, 0.1);
  X.linear() = so3::Exp(std::numbers::pi * testing::RandomUnitVector(rng));
  std::vector<Motion> motions;
  for (double angle : {0.7, 2.9}) {
    const Eigen::Vector3d t = testing::RandomPose(rng).translation();  // drawn before the axis
    const Pose B = MakePose(so3::Exp(angle * testing::RandomUnitVector(rng)), t);
    motions.push_back({X * B * X.inverse(), B, 0, 1});
  }
  testing::ExpectPoseNear(GetParam().solve(motions), X, 1e-9, "X");
}

// Every motion an EXACT half-turn (three different axes): the quaternion scalar parts are all 0,
// so canonical signs (and the sign of log at π) are arbitrary on both sides.
TEST_P(RotationThenTranslation, ExactWhenEveryMotionIsAHalfTurn) {
  std::mt19937_64 rng(GetParam().seed + 1);
  const Pose X = testing::RandomPose(rng, 0.1);
  std::vector<Motion> motions;
  for (const Eigen::Vector3d& axis :
       {Eigen::Vector3d(1.0, 0.0, 0.0), Eigen::Vector3d(1.0, 1.0, 0.0).normalized(),
        Eigen::Vector3d(0.2, -0.5, 0.9).normalized()}) {
    const Pose B =
        MakePose(so3::Exp(std::numbers::pi * axis), testing::RandomPose(rng).translation());
    motions.push_back({X * B * X.inverse(), B, 0, 1});
  }
  testing::ExpectPoseNear(GetParam().solve(motions), X, 1e-9, "X");
}

// 200 seeded thesis-protocol data sets, n = 5…15, σ = 0.3 mm / 0.3° on robot and camera: no
// catastrophic trial (> 10°, the acceptance criterion of docs/thesis-study.md).
TEST_P(RotationThenTranslation, NoCatastrophicTrialWithNoise) {
  const testing::NoisyStudy study = testing::RunNoisyStudy(ProblemSolver(), 200, GetParam().seed);
  EXPECT_LT(study.worst_rotation_deg, 10.0);
  EXPECT_LT(study.median_rotation_deg, 0.5);
}

// Parallel axes, pure translations, 2 stations and no motion at all: DegenerateError, never a
// number (the solver alone, without the dispatcher's observability check).
TEST_P(RotationThenTranslation, DegenerateDataThrow) {
  testing::ExpectDegenerateDataThrow(ProblemSolver());
  EXPECT_THROW(GetParam().solve({}), DegenerateError);
}

// Real data (small rotations mixed with pure translations): within the upstream tolerance of
// 1° / 50 mm of Tabb's reference.
TEST_P(RotationThenTranslation, RealDataTabbDataset1) {
  testing::ExpectWithinTabbTolerance(ProblemSolver(), GetParam().name);
}

INSTANTIATE_TEST_SUITE_P(Solvers, RotationThenTranslation, ::testing::ValuesIn(kSolvers),
                         [](const ::testing::TestParamInfo<Solver>& param) {
                           return std::string(param.param.name);
                         });

}  // namespace
}  // namespace hecal::handeye
