// Euler angles checked against an independent definition written out here
// (docs/conventions.md#euler-angles): elementary rotations as explicit matrices, and the two
// conventions built from their geometric meaning — extrinsic: rotate about the fixed world axes,
// one after the other; intrinsic: rotate about the current (moving) body axes, one after the other.
// Neither uses the code under test.
#include "hecal/geometry/euler.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "geometry/geometry_test_util.h"
#include "hecal/core/random_draws.h"
#include "testing/random_poses.h"

namespace hecal {
namespace {

// --- independent reference ---------------------------------------------------------------------

Eigen::Matrix3d RefRx(double a) {
  Eigen::Matrix3d R;
  R << 1, 0, 0,                      //
      0, std::cos(a), -std::sin(a),  //
      0, std::sin(a), std::cos(a);
  return R;
}
Eigen::Matrix3d RefRy(double a) {
  Eigen::Matrix3d R;
  R << std::cos(a), 0, std::sin(a),  //
      0, 1, 0,                       //
      -std::sin(a), 0, std::cos(a);
  return R;
}
Eigen::Matrix3d RefRz(double a) {
  Eigen::Matrix3d R;
  R << std::cos(a), -std::sin(a), 0,  //
      std::sin(a), std::cos(a), 0,    //
      0, 0, 1;
  return R;
}
Eigen::Matrix3d RefElementary(char letter, double a) {
  switch (std::tolower(static_cast<unsigned char>(letter))) {
    case 'x':
      return RefRx(a);
    case 'y':
      return RefRy(a);
    default:
      return RefRz(a);
  }
}

// By the meaning of the words: each step rotates the body by the angle about an axis that is
// either the fixed world axis (extrinsic) or the body's own axis as it is now (intrinsic). A
// rotation about a world-frame axis u is applied on the left: R ← AngleAxis(a, u) · R.
Eigen::Matrix3d RefEulerGeometric(const std::string& seq, const Eigen::Vector3d& angles) {
  const bool intrinsic = std::isupper(static_cast<unsigned char>(seq[0])) != 0;
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  for (int i = 0; i < 3; ++i) {
    const int axis = std::tolower(static_cast<unsigned char>(seq[static_cast<size_t>(i)])) - 'x';
    const Eigen::Vector3d fixed_axis = Eigen::Vector3d::Unit(axis);
    const Eigen::Vector3d axis_now = intrinsic ? Eigen::Vector3d(R * fixed_axis) : fixed_axis;
    R = Eigen::AngleAxisd(angles(i), axis_now).toRotationMatrix() * R;
  }
  return R;
}

// The same as a product of the explicit matrices: intrinsic "XYZ" = Rx Ry Rz, extrinsic "xyz"
// = Rz Ry Rx.
Eigen::Matrix3d RefEulerProduct(const std::string& seq, const Eigen::Vector3d& angles) {
  const Eigen::Matrix3d E1 = RefElementary(seq[0], angles(0));
  const Eigen::Matrix3d E2 = RefElementary(seq[1], angles(1));
  const Eigen::Matrix3d E3 = RefElementary(seq[2], angles(2));
  const bool intrinsic = std::isupper(static_cast<unsigned char>(seq[0])) != 0;
  return intrinsic ? Eigen::Matrix3d(E1 * E2 * E3) : Eigen::Matrix3d(E3 * E2 * E1);
}

bool IsProper(const std::string& seq) {
  return std::tolower(static_cast<unsigned char>(seq[0])) ==
         std::tolower(static_cast<unsigned char>(seq[2]));
}

EulerSequence Seq(const std::string& text) {
  const std::optional<EulerSequence> parsed = EulerSequence::Parse(text);
  EXPECT_TRUE(parsed.has_value()) << text;
  return parsed.value_or(*EulerSequence::Parse("xyz"));
}

// The a1 that carries the rotation at gimbal lock when a3 is set to 0, derived in the test from
// the lock identities: for Tait–Bryan E_q(θ) E_r(φ) = E_p(s sin θ φ) E_q(θ) at θ = ±π/2 with
// s = +1 for the cyclic order p→q (x→y→z), so intrinsic a1 + s sin(a2) a3 and extrinsic
// a1 − s sin(a2) a3; for proper sequences a1 + a3 at a2 = 0 and a1 − a3 at a2 = π.
double LockedFirstAngle(const std::string& seq, const Eigen::Vector3d& a) {
  if (IsProper(seq)) return a(0) + std::cos(a(1)) * a(2);
  const int p = std::tolower(static_cast<unsigned char>(seq[0])) - 'x';
  const int q = std::tolower(static_cast<unsigned char>(seq[1])) - 'x';
  const double s = (q - p + 3) % 3 == 1 ? 1.0 : -1.0;
  const bool intrinsic = std::isupper(static_cast<unsigned char>(seq[0])) != 0;
  return a(0) + (intrinsic ? 1.0 : -1.0) * s * std::sin(a(1)) * a(2);
}

// Asserts the documented output ranges.
void ExpectInRange(const std::string& seq, const Eigen::Vector3d& a) {
  EXPECT_GT(a(0), -std::numbers::pi) << seq;
  EXPECT_LE(a(0), std::numbers::pi) << seq;
  EXPECT_GT(a(2), -std::numbers::pi) << seq;
  EXPECT_LE(a(2), std::numbers::pi) << seq;
  if (IsProper(seq)) {
    EXPECT_GE(a(1), 0.0) << seq;
    EXPECT_LE(a(1), std::numbers::pi) << seq;
  } else {
    EXPECT_GE(a(1), -std::numbers::pi / 2) << seq;
    EXPECT_LE(a(1), std::numbers::pi / 2) << seq;
  }
}

// --- the reference itself ---------------------------------------------------------------------

TEST(EulerReference, GeometricAndProductDefinitionsAgree) {
  // Guards the test's own two definitions against each other (moving vs fixed axes).
  std::mt19937_64 rng(7);
  hecal::UniformRealDistribution angle(-std::numbers::pi, std::numbers::pi);
  for (const std::string& seq : AllSequences()) {
    for (int n = 0; n < 50; ++n) {
      // Drawn last to first: the order these tests' data were generated in.
      const double a3 = angle(rng), a2 = angle(rng), a1 = angle(rng);
      const Eigen::Vector3d a(a1, a2, a3);
      EXPECT_LT(MaxAbs(RefEulerGeometric(seq, a) - RefEulerProduct(seq, a)), 1e-14) << seq;
    }
  }
}

// --- elementary rotations and MatrixFromEuler ------------------------------------------------

TEST(Euler, ElementaryRotationsAreRightHanded) {
  const double a = 0.37;
  EXPECT_LT(MaxAbs(ElementaryRotation(0, a) - RefRx(a)), 1e-16);
  EXPECT_LT(MaxAbs(ElementaryRotation(1, a) - RefRy(a)), 1e-16);
  EXPECT_LT(MaxAbs(ElementaryRotation(2, a) - RefRz(a)), 1e-16);
  // A quarter turn about z takes x to y, about x takes y to z, about y takes z to x.
  const double h = std::numbers::pi / 2;
  EXPECT_LT((ElementaryRotation(2, h) * Eigen::Vector3d::UnitX() - Eigen::Vector3d::UnitY()).norm(),
            1e-15);
  EXPECT_LT((ElementaryRotation(0, h) * Eigen::Vector3d::UnitY() - Eigen::Vector3d::UnitZ()).norm(),
            1e-15);
  EXPECT_LT((ElementaryRotation(1, h) * Eigen::Vector3d::UnitZ() - Eigen::Vector3d::UnitX()).norm(),
            1e-15);
}

TEST(Euler, MatrixFromEulerMatchesIndependentDefinition) {
  std::mt19937_64 rng(11);
  hecal::UniformRealDistribution angle(-4.0, 4.0);  // beyond ±π on purpose
  for (const std::string& seq : AllSequences()) {
    const EulerSequence sequence = Seq(seq);
    for (int n = 0; n < 200; ++n) {
      const double a3 = angle(rng), a2 = angle(rng), a1 = angle(rng);
      const Eigen::Vector3d a(a1, a2, a3);
      EXPECT_LT(MaxAbs(MatrixFromEuler(a, sequence) - RefEulerGeometric(seq, a)), 1e-14)
          << seq << " " << a.transpose();
    }
  }
}

TEST(Euler, KnownClosedForms) {
  // Yaw–pitch–roll written out (e.g. Craig, "Introduction to Robotics", eq. 2.64 for X–Y–Z fixed
  // angles): extrinsic xyz (γ, β, α) = Rz(α) Ry(β) Rx(γ).
  const double g = 0.3, b = -0.7, al = 2.1;
  const double ca = std::cos(al), sa = std::sin(al), cb = std::cos(b), sb = std::sin(b),
               cg = std::cos(g), sg = std::sin(g);
  Eigen::Matrix3d R;
  R << ca * cb, ca * sb * sg - sa * cg, ca * sb * cg + sa * sg,  //
      sa * cb, sa * sb * sg + ca * cg, sa * sb * cg - ca * sg,   //
      -sb, cb * sg, cb * cg;
  EXPECT_LT(MaxAbs(MatrixFromEuler({g, b, al}, Seq("xyz")) - R), 1e-15);
  EXPECT_LT(MaxAbs(MatrixFromEuler({al, b, g}, Seq("ZYX")) - R), 1e-15);
  // Extrinsic xyz with a quarter turn about x only: y goes to z.
  EXPECT_LT((MatrixFromEuler({std::numbers::pi / 2, 0, 0}, Seq("xyz")) * Eigen::Vector3d::UnitY() -
             Eigen::Vector3d::UnitZ())
                .norm(),
            1e-15);
  // Intrinsic ZYX (KUKA A, B, C) = Rz(A) Ry(B) Rx(C): with A = B = 90° the tool x axis points
  // down: Ry(90°) takes x to −z, which Rz leaves alone.
  const Eigen::Matrix3d K =
      MatrixFromEuler({std::numbers::pi / 2, std::numbers::pi / 2, 0}, Seq("ZYX"));
  EXPECT_LT((K * Eigen::Vector3d::UnitX() - Eigen::Vector3d(0, 0, -1)).norm(), 1e-15);
}

// --- EulerFromMatrix -----------------------------------------------------------------------------

TEST(Euler, RecoversGeneratingAnglesAwayFromLock) {
  // Uniqueness: inside the documented ranges and away from the lock the angles are unique, so
  // EulerFromMatrix must return exactly the angles the rotation was built from.
  std::mt19937_64 rng(23);
  hecal::UniformRealDistribution outer(-std::numbers::pi, std::numbers::pi);
  for (const std::string& seq : AllSequences()) {
    const EulerSequence sequence = Seq(seq);
    const double lo = IsProper(seq) ? 0.0 : -std::numbers::pi / 2;
    const double hi = IsProper(seq) ? std::numbers::pi : std::numbers::pi / 2;
    hecal::UniformRealDistribution middle(lo, hi);
    double worst = 0.0;
    for (int n = 0; n < 2000; ++n) {
      const double a3 = outer(rng), a2 = middle(rng), a1 = outer(rng);
      const Eigen::Vector3d a(a1, a2, a3);
      const double distance = IsProper(seq) ? std::min(a(1), std::numbers::pi - a(1))
                                            : std::numbers::pi / 2 - std::abs(a(1));
      if (distance < 1e-4) continue;  // angle error grows as 1e-16 / distance
      const Eigen::Vector3d b = EulerFromMatrix(RefEulerProduct(seq, a), sequence);
      ExpectInRange(seq, b);
      for (int i = 0; i < 3; ++i) worst = std::max(worst, AngleDifference(a(i), b(i)));
    }
    EXPECT_LT(worst, 1e-11) << seq;
  }
}

TEST(Euler, RoundTripOnRandomRotations) {
  std::mt19937_64 rng(29);
  for (const std::string& seq : AllSequences()) {
    const EulerSequence sequence = Seq(seq);
    double worst = 0.0;
    for (int n = 0; n < 3000; ++n) {
      const Eigen::Matrix3d R = testing::RandomRotation(rng);
      const Eigen::Vector3d a = EulerFromMatrix(R, sequence);
      ExpectInRange(seq, a);
      worst = std::max(worst, MaxAbs(RefEulerProduct(seq, a) - R));
    }
    EXPECT_LT(worst, 1e-14) << seq;
  }
}

TEST(Euler, RoundTripOnEdgeCaseRotations) {
  // Identity, exactly π about each axis, tiny angles, near π (testing::EdgeCaseRotationVectors).
  std::mt19937_64 rng(31);
  const std::vector<Eigen::Vector3d> cases = testing::EdgeCaseRotationVectors(rng);
  for (const std::string& seq : AllSequences()) {
    const EulerSequence sequence = Seq(seq);
    for (const Eigen::Vector3d& omega : cases) {
      const double theta = omega.norm();
      const Eigen::Matrix3d R = theta == 0.0
                                    ? Eigen::Matrix3d::Identity()
                                    : Eigen::AngleAxisd(theta, omega / theta).toRotationMatrix();
      const Eigen::Vector3d a = EulerFromMatrix(R, sequence);
      ExpectInRange(seq, a);
      // Tiny rotations fall inside the lock band of the proper sequences (middle angle ≈ 0),
      // where a3 = 0 costs O(middle angle · |a3|) ≤ 1e-7 · π; elsewhere the round trip is exact.
      const bool in_band = IsProper(seq) && (a(1) < kGimbalLockTolerance ||
                                             a(1) > std::numbers::pi - kGimbalLockTolerance);
      EXPECT_LT(MaxAbs(RefEulerProduct(seq, a) - R), in_band ? 4e-7 : 1e-14)
          << seq << " " << omega.transpose();
    }
  }
}

TEST(Euler, IdentityAndQuarterTurnsGiveExactAngles) {
  for (const std::string& seq : AllSequences()) {
    const Eigen::Vector3d a = EulerFromMatrix(Eigen::Matrix3d::Identity(), Seq(seq));
    EXPECT_EQ(a(0), 0.0) << seq;
    EXPECT_EQ(a(2), 0.0) << seq;
    EXPECT_EQ(a(1), 0.0) << seq;
  }
  // Exactly representable: π about x as diag(1, −1, −1) in extrinsic xyz is (π, 0, 0), never −π.
  const Eigen::Matrix3d Rx_pi = Eigen::Vector3d(1, -1, -1).asDiagonal();
  const Eigen::Vector3d a = EulerFromMatrix(Rx_pi, Seq("xyz"));
  EXPECT_EQ(a(0), std::numbers::pi);
  EXPECT_EQ(a(1), 0.0);
  EXPECT_EQ(a(2), 0.0);
  EXPECT_FALSE(std::signbit(a(1))) << "no negative zero";
  const Eigen::Vector3d b = EulerFromMatrix(Rx_pi, Seq("ZYX"));
  EXPECT_EQ(b(0), 0.0);
  EXPECT_EQ(b(2), std::numbers::pi);
}

TEST(Euler, AnglesNearPlusMinusPiWrapIntoRange) {
  std::mt19937_64 rng(37);
  for (const std::string& seq : AllSequences()) {
    const EulerSequence sequence = Seq(seq);
    const double mid = IsProper(seq) ? 1.1 : 0.4;
    for (const double a1 :
         {std::numbers::pi, -std::numbers::pi, std::numbers::pi - 1e-12, -std::numbers::pi + 1e-12,
          std::numbers::pi - 1e-9, -std::numbers::pi + 1e-9}) {
      for (const double a3 : {std::numbers::pi, -std::numbers::pi, std::numbers::pi - 1e-10,
                              -std::numbers::pi + 1e-10, 0.5}) {
        const Eigen::Vector3d a(a1, mid, a3);
        const Eigen::Matrix3d R = RefEulerProduct(seq, a);
        const Eigen::Vector3d b = EulerFromMatrix(R, sequence);
        ExpectInRange(seq, b);  // −π itself must come back as +π
        EXPECT_LT(AngleDifference(a(0), b(0)), 1e-12) << seq << " " << a.transpose();
        EXPECT_LT(std::abs(a(1) - b(1)), 1e-12) << seq << " " << a.transpose();
        EXPECT_LT(AngleDifference(a(2), b(2)), 1e-12) << seq << " " << a.transpose();
        EXPECT_LT(MaxAbs(RefEulerProduct(seq, b) - R), 1e-14) << seq;
      }
    }
  }
}

TEST(Euler, GimbalLockExactlyAtTheLock) {
  std::mt19937_64 rng(41);
  hecal::UniformRealDistribution outer(-std::numbers::pi, std::numbers::pi);
  for (const std::string& seq : AllSequences()) {
    const EulerSequence sequence = Seq(seq);
    const std::vector<double> locks =
        IsProper(seq) ? std::vector<double>{0.0, std::numbers::pi}
                      : std::vector<double>{std::numbers::pi / 2, -std::numbers::pi / 2};
    for (const double lock : locks) {
      for (int n = 0; n < 200; ++n) {
        const double a3 = outer(rng), a1 = outer(rng);
        const Eigen::Vector3d a(a1, lock, a3);
        const Eigen::Matrix3d R = RefEulerProduct(seq, a);
        const Eigen::Vector3d b = EulerFromMatrix(R, sequence);
        ExpectInRange(seq, b);
        EXPECT_EQ(b(2), 0.0) << seq << ": a3 is zero at the lock";
        EXPECT_LT(std::abs(b(1) - lock), 1e-12) << seq;
        EXPECT_LT(AngleDifference(b(0), LockedFirstAngle(seq, a)), 1e-12)
            << seq << " " << a.transpose() << " -> " << b.transpose();
        EXPECT_LT(MaxAbs(RefEulerProduct(seq, b) - R), 1e-12) << seq;
      }
    }
  }
}

TEST(Euler, GimbalLockIsDeterministicAcrossEquivalentInputs) {
  // Many (a1, a3) pairs give the same locked rotation; all must map to one answer.
  for (const std::string& seq : AllSequences()) {
    const EulerSequence sequence = Seq(seq);
    const double lock = IsProper(seq) ? std::numbers::pi : -std::numbers::pi / 2;
    const Eigen::Vector3d first = EulerFromMatrix(RefEulerProduct(seq, {0.9, lock, 0.0}), sequence);
    for (const double shift : {-2.0, -0.5, 0.25, 1.0, 3.0}) {
      // The same combined angle 0.9: a1 + k·a3 = 0.9 with a3 = shift (k = ±1 from the identity).
      const Eigen::Vector3d a(0.9 - LockedFirstAngle(seq, {0.0, lock, shift}), lock, shift);
      const Eigen::Vector3d b = EulerFromMatrix(RefEulerProduct(seq, a), sequence);
      EXPECT_LT((b - first).cwiseAbs().maxCoeff(), 1e-12) << seq << " shift " << shift;
    }
  }
}

TEST(Euler, CloseToTheLockOutsideTheBandIsExact) {
  // 1e-6 and 1e-5 from the lock: no lock handling, all three angles are recovered, and the
  // reconstruction is exact because a3 is extracted after removing a1.
  std::mt19937_64 rng(43);
  hecal::UniformRealDistribution outer(-std::numbers::pi, std::numbers::pi);
  for (const std::string& seq : AllSequences()) {
    const EulerSequence sequence = Seq(seq);
    for (const double delta : {1e-6, 1e-5, 1e-7 * 1.5}) {
      const std::vector<double> middles =
          IsProper(seq)
              ? std::vector<double>{delta, std::numbers::pi - delta}
              : std::vector<double>{std::numbers::pi / 2 - delta, -std::numbers::pi / 2 + delta};
      for (const double mid : middles) {
        for (int n = 0; n < 100; ++n) {
          const double a3 = outer(rng), a1 = outer(rng);
          const Eigen::Vector3d a(a1, mid, a3);
          const Eigen::Matrix3d R = RefEulerProduct(seq, a);
          const Eigen::Vector3d b = EulerFromMatrix(R, sequence);
          ExpectInRange(seq, b);
          EXPECT_LT(MaxAbs(RefEulerProduct(seq, b) - R), 1e-12) << seq << " δ=" << delta;
          EXPECT_LT(std::abs(b(1) - mid), 1e-14) << seq;
          // a1 and a3 individually are only determined to ~1e-16 / δ.
          EXPECT_LT(AngleDifference(b(0), a(0)), 1e-15 / delta * 100) << seq << " δ=" << delta;
          EXPECT_LT(AngleDifference(b(2), a(2)), 1e-15 / delta * 100) << seq << " δ=" << delta;
        }
      }
    }
  }
}

TEST(Euler, InsideTheLockBand) {
  // 1e-8 from the lock (inside kGimbalLockTolerance): a3 = 0 and a1 carries the rotation. A
  // rotation with a3 = 0 there is reproduced exactly; in general only to O(δ · |a3|), which is
  // the cost of the convention (no (a1, a2, 0) reproduces such a rotation better).
  std::mt19937_64 rng(47);
  hecal::UniformRealDistribution outer(-std::numbers::pi, std::numbers::pi);
  const double delta = 1e-8;
  for (const std::string& seq : AllSequences()) {
    const EulerSequence sequence = Seq(seq);
    const std::vector<double> middles =
        IsProper(seq)
            ? std::vector<double>{delta, std::numbers::pi - delta}
            : std::vector<double>{std::numbers::pi / 2 - delta, -std::numbers::pi / 2 + delta};
    for (const double mid : middles) {
      for (int n = 0; n < 100; ++n) {
        const Eigen::Vector3d on_manifold(outer(rng), mid, 0.0);
        const Eigen::Matrix3d R0 = RefEulerProduct(seq, on_manifold);
        const Eigen::Vector3d b0 = EulerFromMatrix(R0, sequence);
        EXPECT_EQ(b0(2), 0.0) << seq;
        EXPECT_LT((b0 - on_manifold).cwiseAbs().maxCoeff(), 1e-12) << seq;
        EXPECT_LT(MaxAbs(RefEulerProduct(seq, b0) - R0), 1e-12) << seq;

        const double a3 = outer(rng), a1 = outer(rng);
        const Eigen::Vector3d a(a1, mid, a3);
        const Eigen::Matrix3d R = RefEulerProduct(seq, a);
        const Eigen::Vector3d b = EulerFromMatrix(R, sequence);
        ExpectInRange(seq, b);
        EXPECT_EQ(b(2), 0.0) << seq;
        EXPECT_LT(std::abs(b(1) - mid), 1e-14) << seq;
        EXPECT_LT(AngleDifference(b(0), LockedFirstAngle(seq, a)), 2.0 * delta) << seq;
        EXPECT_LT(MaxAbs(RefEulerProduct(seq, b) - R), 2.0 * delta * std::abs(a(2)) + 1e-14)
            << seq << " " << a.transpose();
      }
    }
  }
}

// --- EulerSequence ------------------------------------------------------------------------------

TEST(EulerSequence, ParseAcceptsValidSequences) {
  for (const std::string& seq : AllSequences()) {
    const std::optional<EulerSequence> parsed = EulerSequence::Parse(seq);
    ASSERT_TRUE(parsed.has_value()) << seq;
    EXPECT_EQ(parsed->ToString(), seq);
    EXPECT_EQ(parsed->intrinsic(), std::isupper(static_cast<unsigned char>(seq[0])) != 0);
    EXPECT_EQ(parsed->proper(), IsProper(seq));
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(parsed->axes()[static_cast<size_t>(i)],
                std::tolower(static_cast<unsigned char>(seq[static_cast<size_t>(i)])) - 'x');
    }
  }
  EXPECT_EQ(AllSequences().size(), 24u);
  const EulerSequence zxz = *EulerSequence::Parse("zxz");
  EXPECT_FALSE(zxz.intrinsic());
  EXPECT_TRUE(zxz.proper());
  EXPECT_EQ(zxz.axes(), (std::array<int, 3>{2, 0, 2}));
  const EulerSequence ZYX = *EulerSequence::Parse("ZYX");
  EXPECT_TRUE(ZYX.intrinsic());
  EXPECT_FALSE(ZYX.proper());
  EXPECT_TRUE(EulerSequence::Parse("xyz").has_value());
  EXPECT_TRUE(EulerSequence::Parse("ZXZ").has_value());
}

TEST(EulerSequence, ParseRejectsInvalidText) {
  for (const char* text : {"xYz", "Xyz", "xyZ", "xxy", "xyy", "XXY", "ZZZ", "xy", "abc", "", "x",
                           "xyzx", "xyz ", " xyz", "x-z", "uvw", "XYW", "123"}) {
    EXPECT_FALSE(EulerSequence::Parse(text).has_value()) << '"' << text << '"';
  }
  EXPECT_FALSE(EulerSequence::Parse(std::string_view("x\0z", 3)).has_value());
}

TEST(EulerSequence, ReversedIsTheSameRotation) {
  std::mt19937_64 rng(53);
  hecal::UniformRealDistribution angle(-std::numbers::pi, std::numbers::pi);
  EXPECT_EQ(Seq("xyz").Reversed(), Seq("ZYX"));
  EXPECT_EQ(Seq("ZYX").Reversed(), Seq("xyz"));
  EXPECT_EQ(Seq("zxz").Reversed(), Seq("ZXZ"));
  EXPECT_EQ(Seq("XZY").Reversed().ToString(), "yzx");
  for (const std::string& seq : AllSequences()) {
    const EulerSequence s = Seq(seq);
    EXPECT_EQ(s.Reversed().Reversed(), s);
    EXPECT_NE(s.Reversed().intrinsic(), s.intrinsic());
    for (int n = 0; n < 100; ++n) {
      const double a3 = angle(rng), a2 = angle(rng), a1 = angle(rng);
      const Eigen::Vector3d a(a1, a2, a3);
      const Eigen::Vector3d reversed(a(2), a(1), a(0));
      EXPECT_LT(MaxAbs(MatrixFromEuler(a, s) - MatrixFromEuler(reversed, s.Reversed())), 1e-15);
      // Away from the lock the decomposition is unique, so both read the same three angles.
      const Eigen::Matrix3d R = RefEulerProduct(seq, a);
      const Eigen::Vector3d b = EulerFromMatrix(R, s);
      const Eigen::Vector3d c = EulerFromMatrix(R, s.Reversed());
      const double distance = IsProper(seq) ? std::min(b(1), std::numbers::pi - b(1))
                                            : std::numbers::pi / 2 - std::abs(b(1));
      if (distance < 1e-4) continue;
      for (int i = 0; i < 3; ++i) EXPECT_LT(AngleDifference(b(i), c(2 - i)), 1e-11) << seq;
    }
  }
  // The example of the header, with numbers: extrinsic xyz (a, b, c) == intrinsic ZYX (c, b, a).
  const Eigen::Vector3d abc(0.1, -0.2, 0.3);
  EXPECT_LT(
      MaxAbs(MatrixFromEuler(abc, Seq("xyz")) - MatrixFromEuler({0.3, -0.2, 0.1}, Seq("ZYX"))),
      1e-16);
}

TEST(EulerSequence, ExtrinsicAndIntrinsicDifferForTheSameLetters) {
  // Guards against treating case as decoration: "xyz" and "XYZ" are different rotations.
  const Eigen::Vector3d a(0.3, 0.5, 0.7);
  EXPECT_GT(MaxAbs(MatrixFromEuler(a, Seq("xyz")) - MatrixFromEuler(a, Seq("XYZ"))), 0.1);
}

// --- the contour paper's ZXZ form (docs/contour.md#motion-from-an-affinity)
// ------------------------------------------------

TEST(Euler, ContourPaperZxzForm) {
  // R = Rz(φ) Rx(θ) Rz(ψ) — intrinsic ZXZ. The paper's affinity M = s · R[0:2, 0:2] satisfies
  // M Mᵀ = Rz(φ) diag(L, L cos²θ) Rz(φ)⁻¹ with L = s²; eigenvector of the larger eigenvalue
  // (cos φ, sin φ), cos θ = sqrt(λ2/λ1). Check hecal's ZXZ against these relations.
  std::mt19937_64 rng(59);
  hecal::UniformRealDistribution outer(-std::numbers::pi, std::numbers::pi);
  hecal::UniformRealDistribution tilt(0.05,
                                      std::numbers::pi / 2 - 0.05);  // the paper's θ ∈ (0, π/2)
  const EulerSequence ZXZ = Seq("ZXZ");
  for (int n = 0; n < 500; ++n) {
    const double phi = outer(rng), theta = tilt(rng), psi = outer(rng);
    const Eigen::Matrix3d R = MatrixFromEuler({phi, theta, psi}, ZXZ);
    EXPECT_LT(MaxAbs(R - RefRz(phi) * RefRx(theta) * RefRz(psi)), 1e-15);
    const double scale = 0.8;
    const Eigen::Matrix2d M = scale * R.topLeftCorner<2, 2>();
    Eigen::Matrix2d Rphi;
    Rphi << std::cos(phi), -std::sin(phi), std::sin(phi), std::cos(phi);
    const double L = scale * scale;
    const Eigen::Matrix2d expected =
        Rphi * Eigen::Vector2d(L, L * std::cos(theta) * std::cos(theta)).asDiagonal() *
        Rphi.transpose();
    EXPECT_LT((M * M.transpose() - expected).cwiseAbs().maxCoeff(), 1e-14);
    const Eigen::Vector3d back = EulerFromMatrix(R, ZXZ);
    EXPECT_LT(AngleDifference(back(0), phi), 1e-12);
    EXPECT_LT(std::abs(back(1) - theta), 1e-12);
    EXPECT_LT(AngleDifference(back(2), psi), 1e-12);
  }
}

}  // namespace
}  // namespace hecal
