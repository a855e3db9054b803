// Test support (not installed): the properties every Lie group of geometry/ must have, as one
// typed GoogleTest suite (the idea of Sophus' test/core/tests.hpp; the checks here follow the
// definitions of docs/conventions.md). A group enters through a traits struct G:
//
//   Element, Tangent (an Eigen vector of kDof rows: rotation vector first, then translation)
//   Exp(ξ), Log(g), Compose(a, b) = a·b, Inverse(g), Identity()
//   Adjoint(g)           g · Exp(δ) · g⁻¹ = Exp(Ad(g) δ)
//   RightJacobian(ξ), LeftJacobian(ξ) and their inverses:
//                        Exp(ξ + δ) ≈ Exp(ξ) · Exp(Jr(ξ) δ) ≈ Exp(Jl(ξ) δ) · Exp(ξ);
//                        Log(g · Exp(δ)) ≈ Log(g) + Jr⁻¹ δ, Log(Exp(δ) · g) ≈ Log(g) + Jl⁻¹ δ
//   Distance(a, b)       largest entry of the difference of the two 4 × 4 (3 × 3) matrices
//   tolerances           kExpLog (· (1 + |t|)), kLogExpRotation (· min(1, |ω|)),
//                        kLogExpTranslation (· (1 + |v|)), kGroup, kJacobian, kInverseJacobian
//
// The properties, each on random samples plus the edge cases of testing/random_poses.h (0, tiny
// angles, both sides of the series switches, π − 1e-9 … and exactly π):
//  - Exp∘Log = id on elements (every angle up to and including π);
//  - Log∘Exp = id on tangents with |ω| < π (the rotation part relative at tiny angles);
//  - group axioms: Exp(0) = identity, identity and inverse laws, associativity;
//  - the adjoint conjugates the exponential and is a homomorphism, Ad(a·b) = Ad(a) Ad(b);
//  - the four Jacobians against five-point central differences of Exp and Log.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "hecal/core/random_draws.h"
#include "testing/random_poses.h"

namespace hecal::testing {

template <class G>
class LieGroupTest : public ::testing::Test {
 protected:
  using Tangent = typename G::Tangent;
  using Jacobian = Eigen::Matrix<double, G::kDof, G::kDof>;
  static constexpr double kPi = std::numbers::pi;
  static constexpr int kSamples = 2000;

  // ω with the given angle about a random axis; v (if any) Gaussian with σ = 1.
  static Tangent RandomTangent(std::mt19937_64& rng, double angle) {
    Tangent xi;
    xi.template head<3>() = RandomRotationVector(rng, angle);
    hecal::NormalDistribution normal;
    for (int k = 3; k < G::kDof; ++k) xi(k) = normal(rng);
    return xi;
  }

  // Random angles in [0, max_angle) plus the edge-case angles up to max_angle (inclusive when
  // `inclusive`).
  static std::vector<Tangent> Tangents(std::mt19937_64& rng, double max_angle, bool inclusive) {
    std::vector<Tangent> result;
    hecal::UniformRealDistribution angle(0.0, max_angle);
    for (int i = 0; i < kSamples; ++i) result.push_back(RandomTangent(rng, angle(rng)));
    for (const Eigen::Vector3d& omega : EdgeCaseRotationVectors(rng)) {
      if (omega.norm() < max_angle || (inclusive && omega.norm() <= max_angle)) {
        Tangent xi = RandomTangent(rng, 0.0);
        xi.template head<3>() = omega;
        result.push_back(xi);
      }
    }
    return result;
  }

  // Angles at which the Jacobians are checked: zero, tiny, both sides of the series switches
  // (1e-2 and 0.1 for the rotation; 2e-4 and 2e-2 for the dual quaternion's half angles),
  // generic, and near π.
  static const std::vector<double>& JacobianAngles() {
    static const std::vector<double> angles = {
        0.0,     1e-9,   1e-6,   1e-4, 1.99e-4, 2.01e-4, 0.99e-2, 1.01e-2,    1.99e-2,
        2.01e-2, 0.0999, 0.1001, 0.5,  1.0,     2.0,     3.0,     kPi - 1e-2, kPi - 1e-3};
    return angles;
  }

  // Central five-point derivative of f: R^kDof → R^kDof at δ = 0 (error O(h⁴)).
  template <class F>
  static Jacobian NumericJacobian(const F& f, double h) {
    Jacobian J;
    for (int j = 0; j < G::kDof; ++j) {
      const Tangent e = h * Tangent::Unit(j);
      J.col(j) = (8.0 * (f(e) - f(-e)) - (f(2.0 * e) - f(-2.0 * e))) / (12.0 * h);
    }
    return J;
  }

  static double TranslationNorm(const Tangent& xi) {
    return xi.template tail<G::kDof - 3>().norm();
  }
};

TYPED_TEST_SUITE_P(LieGroupTest);

TYPED_TEST_P(LieGroupTest, ExpOfLogIsIdentity) {
  using G = TypeParam;
  std::mt19937_64 rng(601);
  for (const auto& xi : this->Tangents(rng, this->kPi, true)) {
    const typename G::Element g = G::Exp(xi);
    EXPECT_LT(G::Distance(G::Exp(G::Log(g)), g), G::kExpLog * (1 + this->TranslationNorm(xi)))
        << xi.transpose();
  }
}

TYPED_TEST_P(LieGroupTest, LogOfExpIsIdentityBelowPi) {
  using G = TypeParam;
  std::mt19937_64 rng(602);
  for (const auto& xi : this->Tangents(rng, this->kPi, false)) {
    const typename G::Tangent log = G::Log(G::Exp(xi));
    const double angle = xi.template head<3>().norm();
    EXPECT_LE((log - xi).template head<3>().norm(), G::kLogExpRotation * std::min(1.0, angle))
        << xi.transpose();
    EXPECT_LE((log - xi).template tail<G::kDof - 3>().norm(),
              G::kLogExpTranslation * (1 + this->TranslationNorm(xi)))
        << xi.transpose();
  }
}

TYPED_TEST_P(LieGroupTest, SatisfiesTheGroupAxioms) {
  using G = TypeParam;
  std::mt19937_64 rng(603);
  EXPECT_EQ(G::Distance(G::Exp(TestFixture::Tangent::Zero()), G::Identity()), 0.0);
  hecal::UniformRealDistribution angle(0.0, this->kPi);
  for (int i = 0; i < this->kSamples; ++i) {
    const auto a = G::Exp(this->RandomTangent(rng, angle(rng)));
    const auto b = G::Exp(this->RandomTangent(rng, angle(rng)));
    const auto c = G::Exp(this->RandomTangent(rng, angle(rng)));
    EXPECT_LT(G::Distance(G::Compose(a, G::Identity()), a), G::kGroup);
    EXPECT_LT(G::Distance(G::Compose(G::Identity(), a), a), G::kGroup);
    EXPECT_LT(G::Distance(G::Compose(a, G::Inverse(a)), G::Identity()), G::kGroup);
    EXPECT_LT(G::Distance(G::Compose(G::Inverse(a), a), G::Identity()), G::kGroup);
    EXPECT_LT(G::Distance(G::Compose(G::Compose(a, b), c), G::Compose(a, G::Compose(b, c))),
              G::kGroup);
  }
}

TYPED_TEST_P(LieGroupTest, AdjointConjugatesTheExponentialAndIsAHomomorphism) {
  using G = TypeParam;
  std::mt19937_64 rng(604);
  hecal::UniformRealDistribution angle(0.0, this->kPi);
  for (int i = 0; i < this->kSamples; ++i) {
    const auto g = G::Exp(this->RandomTangent(rng, angle(rng)));
    const auto h = G::Exp(this->RandomTangent(rng, angle(rng)));
    const auto delta = this->RandomTangent(rng, 2.0);
    EXPECT_LT(G::Distance(G::Compose(G::Compose(g, G::Exp(delta)), G::Inverse(g)),
                          G::Exp(G::Adjoint(g) * delta)),
              G::kGroup);
    EXPECT_LT((G::Adjoint(G::Compose(g, h)) - G::Adjoint(g) * G::Adjoint(h)).cwiseAbs().maxCoeff(),
              G::kGroup);
  }
}

TYPED_TEST_P(LieGroupTest, JacobiansMatchFiniteDifferences) {
  using G = TypeParam;
  using Twist = typename TestFixture::Tangent;  // the fixture's Tangent, by another name
  std::mt19937_64 rng(605);
  for (double theta : this->JacobianAngles()) {
    // Near π the step of the inverse Jacobians stays well inside the distance to the cut at π.
    const double h_inverse = std::min(1e-3, 0.05 * (this->kPi - theta));
    for (int i = 0; i < 10; ++i) {
      const Twist xi = this->RandomTangent(rng, theta);
      const auto g = G::Exp(xi);
      const auto g_inverse = G::Inverse(g);
      const auto right = [&](const Twist& d) {
        return G::Log(G::Compose(g_inverse, G::Exp(xi + d)));
      };
      const auto left = [&](const Twist& d) {
        return G::Log(G::Compose(G::Exp(xi + d), g_inverse));
      };
      const auto log_right = [&](const Twist& d) { return G::Log(G::Compose(g, G::Exp(d))); };
      const auto log_left = [&](const Twist& d) { return G::Log(G::Compose(G::Exp(d), g)); };
      EXPECT_LT((G::RightJacobian(xi) - this->NumericJacobian(right, 1e-3)).cwiseAbs().maxCoeff(),
                G::kJacobian)
          << theta;
      EXPECT_LT((G::LeftJacobian(xi) - this->NumericJacobian(left, 1e-3)).cwiseAbs().maxCoeff(),
                G::kJacobian)
          << theta;
      EXPECT_LT((G::RightJacobianInverse(xi) - this->NumericJacobian(log_right, h_inverse))
                    .cwiseAbs()
                    .maxCoeff(),
                G::kInverseJacobian)
          << theta;
      EXPECT_LT((G::LeftJacobianInverse(xi) - this->NumericJacobian(log_left, h_inverse))
                    .cwiseAbs()
                    .maxCoeff(),
                G::kInverseJacobian)
          << theta;
    }
  }
}

REGISTER_TYPED_TEST_SUITE_P(LieGroupTest, ExpOfLogIsIdentity, LogOfExpIsIdentityBelowPi,
                            SatisfiesTheGroupAxioms,
                            AdjointConjugatesTheExponentialAndIsAHomomorphism,
                            JacobiansMatchFiniteDifferences);

}  // namespace hecal::testing
