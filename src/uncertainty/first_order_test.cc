#include "hecal/uncertainty/first_order.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "hecal/core/limits.h"
#include "hecal/geometry/se3.h"
#include "testing/options_validity.h"

namespace hecal::uncertainty {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

// y = (x0 x1, sin x2 + x0², exp(x1) x2): analytic Jacobian below.
struct Map {
  template <class T>
  Eigen::Matrix<T, Eigen::Dynamic, 1> operator()(
      const Eigen::Matrix<T, Eigen::Dynamic, 1>& x) const {
    using std::exp;
    using std::sin;
    Eigen::Matrix<T, Eigen::Dynamic, 1> y(3);
    y(0) = x(0) * x(1);
    y(1) = sin(x(2)) + x(0) * x(0);
    y(2) = exp(x(1)) * x(2);
    return y;
  }
};

MatrixXd AnalyticJacobian(const VectorXd& x) {
  MatrixXd J(3, 3);
  J << x(1), x(0), 0.0, 2.0 * x(0), 0.0, std::cos(x(2)), 0.0, std::exp(x(1)) * x(2), std::exp(x(1));
  return J;
}

TEST(AutoDiffJacobian, MatchesTheAnalyticJacobian) {
  const VectorXd x = (VectorXd(3) << 0.3, -1.2, 2.0).finished();
  EXPECT_LT((AutoDiffJacobian(Map{}, x) - AnalyticJacobian(x)).cwiseAbs().maxCoeff(), 1e-14);
}

TEST(NumericJacobian, MatchesTheAnalyticJacobian) {
  const VectorXd x = (VectorXd(3) << 0.3, -1.2, 2.0).finished();
  auto f = [](const VectorXd& v) -> VectorXd { return Map{}(v); };
  EXPECT_LT((NumericJacobian<VectorXd, VectorXd>(f, x) - AnalyticJacobian(x)).cwiseAbs().maxCoeff(),
            1e-8);
}

TEST(NumericJacobian, OfSe3InverseIsMinusTheAdjoint) {
  // (T Exp(δ))⁻¹ = Exp(−δ) T⁻¹ = T⁻¹ Exp(−Ad(T) δ): the Jacobian is −Ad(T), here near π.
  const Pose T = MakePose(so3::Exp(Eigen::Vector3d(0.0, 3.1, 0.1)), Eigen::Vector3d(1, -2, 0.5));
  auto inverse = [](const Pose& P) -> Pose { return P.inverse(); };
  const MatrixXd J = NumericJacobian<Pose, Pose>(inverse, T, 1e-7);
  EXPECT_LT((J + se3::Adjoint(T)).cwiseAbs().maxCoeff(), 1e-6);
}

TEST(FirstOrderTransform, EqualsTheJacobianSandwich) {
  const VectorXd x = (VectorXd(3) << 0.3, -1.2, 2.0).finished();
  MatrixXd C(3, 3);
  C << 0.04, 0.01, 0.0, 0.01, 0.09, 0.0, 0.0, 0.0, 0.01;
  auto f = [](const VectorXd& v) -> VectorXd { return Map{}(v); };
  const Moments<VectorXd> y = FirstOrderTransform<VectorXd, VectorXd>(f, x, C);
  const MatrixXd expected = Propagate(AnalyticJacobian(x), C);
  EXPECT_LT((y.covariance - expected).cwiseAbs().maxCoeff(), 1e-7 * expected.norm());
  EXPECT_LT((y.mean - Map{}(x)).norm(), 1e-15);
  EXPECT_EQ(y.evaluations, 7);
}

TEST(FirstOrderTransform, ExactForLinearMapsAndSkipsNoiseFreeDirections) {
  MatrixXd A(2, 3);
  A << 1.0, -2.0, 0.5, 0.0, 3.0, 1.0;
  MatrixXd C = MatrixXd::Zero(3, 3);
  C(0, 0) = 2.0;
  C(2, 2) = 0.5;
  auto f = [&](const VectorXd& v) -> VectorXd { return A * v; };
  FirstOrderOptions options;
  options.threads = 2;
  const Moments<VectorXd> y =
      FirstOrderTransform<VectorXd, VectorXd>(f, VectorXd::Ones(3), C, options);
  EXPECT_LT((y.covariance - A * C * A.transpose()).cwiseAbs().maxCoeff(), 1e-10);
  EXPECT_EQ(y.evaluations, 5);
}

TEST(CovarianceFromInformation, InvertsAndRefusesSingularInformation) {
  MatrixXd H(2, 2);
  H << 4.0, 1.0, 1.0, 3.0;
  const std::optional<MatrixXd> C = CovarianceFromInformation(H);
  ASSERT_TRUE(C.has_value());
  EXPECT_LT((*C * H - MatrixXd::Identity(2, 2)).norm(), 1e-14);
  MatrixXd singular(2, 2);
  singular << 1.0, 1.0, 1.0, 1.0;
  EXPECT_FALSE(CovarianceFromInformation(singular).has_value());
  EXPECT_FALSE(CovarianceFromInformation(MatrixXd::Zero(0, 0)).has_value());
}

// Straight-line fit y = a + b t with unit-variance noise: Cov = (JᵀJ)⁻¹ with J = [1 t].
TEST(LeastSquaresCovariance, StraightLineFit) {
  MatrixXd J(4, 2);
  J << 1, 0, 1, 1, 1, 2, 1, 3;
  const std::optional<MatrixXd> C = LeastSquaresCovariance(J);
  ASSERT_TRUE(C.has_value());
  // Σ t = 6, Σ t² = 14, n = 4: det = 4·14 − 36 = 20; Cov = [14 −6; −6 4] / 20.
  EXPECT_NEAR((*C)(0, 0), 0.7, 1e-14);
  EXPECT_NEAR((*C)(0, 1), -0.3, 1e-14);
  EXPECT_NEAR((*C)(1, 1), 0.2, 1e-14);
  MatrixXd rank_deficient(3, 2);
  rank_deficient << 1, 2, 2, 4, 3, 6;
  EXPECT_FALSE(LeastSquaresCovariance(rank_deficient).has_value());
}

TEST(FirstOrderOptions, IsValidNamesTheField) {
  using testing::RefusesNaming;
  const FirstOrderOptions defaults;
  EXPECT_TRUE(testing::IsValidOptions(defaults));
  EXPECT_TRUE(RefusesNaming(defaults, "FirstOrderOptions.step", [](auto& o) { o.step = 0.0; }));
  EXPECT_TRUE(RefusesNaming(defaults, "FirstOrderOptions.step",
                            [](auto& o) { o.step = std::numeric_limits<double>::infinity(); }));
  EXPECT_TRUE(
      RefusesNaming(defaults, "FirstOrderOptions.threads", [](auto& o) { o.threads = -2; }));
  EXPECT_TRUE(RefusesNaming(defaults, "FirstOrderOptions.threads",
                            [](auto& o) { o.threads = kMaxThreads + 1; }));
}

}  // namespace
}  // namespace hecal::uncertainty
