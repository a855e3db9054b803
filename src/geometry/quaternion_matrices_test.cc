// Tests for quaternion_matrices.h: Q(r) q = r * q and W(r) q = q * r against Eigen's Hamilton
// product, and the (w, x, y, z) ordering helpers.
#include "hecal/geometry/quaternion_matrices.h"

#include <gtest/gtest.h>

#include <random>

#include "hecal/core/random_draws.h"

namespace hecal {
namespace {

constexpr int kQuaternionMatrixSamples = 2000;

// Not unit on purpose: the product matrices are linear, so they must hold for any 4-vector.
Eigen::Vector4d RandomWxyz(std::mt19937_64& rng) {
  hecal::NormalDistribution normal(0.0, 2.0);
  // Drawn last to first: the order these tests' data were generated in.
  const double z = normal(rng), y = normal(rng), x = normal(rng), w = normal(rng);
  return Eigen::Vector4d(w, x, y, z);
}

// Hamilton product written out from its definition (w1w2 − v1·v2, w1v2 + w2v1 + v1 × v2),
// as a second peer next to Eigen's operator*.
Eigen::Vector4d HamiltonProduct(const Eigen::Vector4d& a, const Eigen::Vector4d& b) {
  const Eigen::Vector3d va = a.tail<3>();
  const Eigen::Vector3d vb = b.tail<3>();
  Eigen::Vector4d r;
  r(0) = a(0) * b(0) - va.dot(vb);
  r.tail<3>() = a(0) * vb + b(0) * va + va.cross(vb);
  return r;
}

TEST(QuaternionMatrices, WxyzHelpersUseScalarFirstOrder) {
  const Eigen::Quaterniond q(1.0, 2.0, 3.0, 4.0);  // Eigen's constructor is (w, x, y, z)
  EXPECT_EQ(ToWxyz(q), Eigen::Vector4d(1, 2, 3, 4));
  EXPECT_EQ(q.coeffs(), Eigen::Vector4d(2, 3, 4, 1));  // storage is (x, y, z, w): not the same
  const Eigen::Quaterniond p = FromWxyz(Eigen::Vector4d(5, 6, 7, 8));
  EXPECT_EQ(p.w(), 5.0);
  EXPECT_EQ(p.x(), 6.0);
  EXPECT_EQ(p.y(), 7.0);
  EXPECT_EQ(p.z(), 8.0);
  std::mt19937_64 rng(21);
  for (int i = 0; i < 100; ++i) {
    const Eigen::Vector4d v = RandomWxyz(rng);
    EXPECT_EQ(ToWxyz(FromWxyz(v)), v);
  }
}

TEST(QuaternionMatrices, LeftMatrixIsLeftHamiltonProduct) {
  std::mt19937_64 rng(22);
  for (int i = 0; i < kQuaternionMatrixSamples; ++i) {
    const Eigen::Vector4d r = RandomWxyz(rng);
    const Eigen::Vector4d q = RandomWxyz(rng);
    const Eigen::Vector4d eigen_product = ToWxyz(FromWxyz(r) * FromWxyz(q));
    const double scale = r.norm() * q.norm();
    EXPECT_LT((QuaternionLeftMatrix(r) * q - eigen_product).norm(), 1e-15 * scale);
    EXPECT_LT((QuaternionLeftMatrix(r) * q - HamiltonProduct(r, q)).norm(), 1e-15 * scale);
  }
}

TEST(QuaternionMatrices, RightMatrixIsRightHamiltonProduct) {
  std::mt19937_64 rng(23);
  for (int i = 0; i < kQuaternionMatrixSamples; ++i) {
    const Eigen::Vector4d r = RandomWxyz(rng);
    const Eigen::Vector4d q = RandomWxyz(rng);
    const Eigen::Vector4d eigen_product = ToWxyz(FromWxyz(q) * FromWxyz(r));
    const double scale = r.norm() * q.norm();
    EXPECT_LT((QuaternionRightMatrix(r) * q - eigen_product).norm(), 1e-15 * scale);
    // Thesis eq. A.1: r * q = Q(r) q = W(q) r.
    EXPECT_LT((QuaternionLeftMatrix(r) * q - QuaternionRightMatrix(q) * r).norm(), 1e-15 * scale);
  }
}

TEST(QuaternionMatrices, BasisProductsFollowHamiltonRule) {
  // i j = k, j i = −k, i² = −1 (Hamilton, not JPL).
  const Eigen::Vector4d one(1, 0, 0, 0), i(0, 1, 0, 0), j(0, 0, 1, 0), k(0, 0, 0, 1);
  EXPECT_EQ(QuaternionLeftMatrix(i) * j, k);
  EXPECT_EQ(QuaternionRightMatrix(j) * i, k);
  EXPECT_EQ(QuaternionLeftMatrix(j) * i, -k);
  EXPECT_EQ(QuaternionLeftMatrix(i) * i, -one);
  EXPECT_EQ(QuaternionLeftMatrix(j) * k, i);
  EXPECT_EQ(QuaternionLeftMatrix(k) * i, j);
  EXPECT_EQ(QuaternionLeftMatrix(one), Eigen::Matrix4d::Identity());
  EXPECT_EQ(QuaternionRightMatrix(one), Eigen::Matrix4d::Identity());
}

TEST(QuaternionMatrices, UnitQuaternionMatricesAreOrthogonalAndCommute) {
  std::mt19937_64 rng(24);
  for (int n = 0; n < kQuaternionMatrixSamples; ++n) {
    const Eigen::Vector4d r = RandomWxyz(rng).normalized();
    const Eigen::Vector4d s = RandomWxyz(rng).normalized();
    const Eigen::Matrix4d Q = QuaternionLeftMatrix(r);
    const Eigen::Matrix4d W = QuaternionRightMatrix(s);
    EXPECT_LT((Q.transpose() * Q - Eigen::Matrix4d::Identity()).norm(), 1e-15 * 8);
    EXPECT_LT((W.transpose() * W - Eigen::Matrix4d::Identity()).norm(), 1e-15 * 8);
    // Associativity (r * q) * s = r * (q * s) means Q(r) and W(s) commute.
    EXPECT_LT((Q * W - W * Q).norm(), 1e-15 * 8);
    // Conjugate ↔ transpose.
    const Eigen::Vector4d r_conj(r(0), -r(1), -r(2), -r(3));
    EXPECT_LT((QuaternionLeftMatrix(r_conj) - Q.transpose()).norm(), 1e-15);
  }
}

}  // namespace
}  // namespace hecal
