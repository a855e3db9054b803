#include "hecal/handeye/translation.h"

#include <gtest/gtest.h>

#include <Eigen/QR>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "hecal/core/error.h"
#include "hecal/geometry/so3.h"
#include "testing/handeye_solver_suite.h"

namespace hecal::handeye {
namespace {

// The dense least-squares solution of the stacked rows (R_A − I) t = R_X t_B − t_A (3N × 3,
// column-pivoting QR): an independent check of the accumulated normal equations.
Eigen::Vector3d DenseSolution(const std::vector<Motion>& motions, const Eigen::Matrix3d& R_X) {
  const Eigen::Index rows = 3 * static_cast<Eigen::Index>(motions.size());
  Eigen::MatrixXd C(rows, 3);
  Eigen::VectorXd d(rows);
  for (size_t k = 0; k < motions.size(); ++k) {
    const Eigen::Index r = 3 * static_cast<Eigen::Index>(k);
    C.middleRows<3>(r) = motions[k].A.linear() - Eigen::Matrix3d::Identity();
    d.segment<3>(r) = R_X * motions[k].B.translation() - motions[k].A.translation();
  }
  return C.colPivHouseholderQr().solve(d);
}

TEST(SolveTranslation, ExactWithTheTrueRotation) {
  for (handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    for (const testing::Scene& data :
         {testing::ThesisCase(setup, 3, 1), testing::ThesisCase(setup, 20, 2),
          testing::WideRotationCase(setup, 6, 3),
          testing::WideRotationCase(setup, 6, 4, std::numbers::pi)}) {
      const Eigen::Vector3d t =
          SolveTranslation(AllPairMotions(data.MeasuredProblem()), data.X.linear());
      EXPECT_LT((t - data.X.translation()).norm(), 1e-12);
    }
  }
}

TEST(SolveTranslation, EqualsTheDenseLeastSquaresSolution) {
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    const testing::Scene data = testing::ThesisCase(handeye::Setup::kEyeInHand, 8, seed,
                                                    1.0 * std::numbers::pi / 180.0, 1e-3);
    const std::vector<Motion> motions = AllPairMotions(data.MeasuredProblem());
    std::mt19937_64 rng(seed);
    const Eigen::Matrix3d R_X =
        data.X.linear() * so3::Exp(testing::RandomRotationVector(rng, 0.02));  // any R_X
    EXPECT_LT((SolveTranslation(motions, R_X) - DenseSolution(motions, R_X)).norm(), 1e-12);
  }
}

// A motion without rotation has R_A − I = 0: whatever its translations, it changes nothing.
TEST(SolveTranslation, MotionsWithoutRotationAddNothing) {
  const testing::Scene data = testing::ThesisCase(handeye::Setup::kEyeInHand, 6, 5);
  std::vector<Motion> motions = AllPairMotions(data.MeasuredProblem());
  const Eigen::Vector3d before = SolveTranslation(motions, data.X.linear());
  motions.push_back({MakePose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(3.0, -2.0, 1.0)),
                     MakePose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(-5.0, 0.0, 7.0)), 0, 1});
  EXPECT_EQ(SolveTranslation(motions, data.X.linear()), before);
}

TEST(SolveTranslation, ParallelAxesNameTheCommonAxis) {
  const testing::Scene data = testing::ParallelAxesCase(handeye::Setup::kEyeInHand, 5, 6);
  const std::vector<Motion> motions = AllPairMotions(data.MeasuredProblem());
  try {
    SolveTranslation(motions, data.X.linear());
    ADD_FAILURE() << "no DegenerateError";
  } catch (const DegenerateError& error) {
    EXPECT_NE(error.unobservable().find("along the common rotation axis"), std::string::npos)
        << error.what();
  }
}

TEST(SolveTranslation, NoRotationAtAllThrows) {
  const testing::Scene data = testing::PureTranslationCase(handeye::Setup::kEyeToHand, 5, 7);
  EXPECT_THROW(SolveTranslation(AllPairMotions(data.MeasuredProblem()), data.X.linear()),
               DegenerateError);
  EXPECT_THROW(SolveTranslation({}, Eigen::Matrix3d::Identity()), DegenerateError);
}

}  // namespace
}  // namespace hecal::handeye
