#include "hecal/io/rotation_input.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "hecal/core/error.h"
#include "testing/elementary_rotations.h"
#include "testing/nearly_orthonormal.h"

namespace hecal::io {
namespace {

using ::testing::AllOf;
using testing::ControllerMatrix;
using ::testing::HasSubstr;
using ::testing::Not;
using testing::Rx;
using testing::Ry;
using testing::Rz;

const Eigen::Matrix3d kR = Rz(0.3) * Ry(-1.2) * Rx(2.5);

// The InputError that reading M raises, checked for the one-line "file:line: what (fix: how)"
// shape.
InputError MatrixError(const Eigen::Matrix3d& M, double rounding = 0.0) {
  RotationInput input("robot.csv");
  try {
    input.Matrix(M, rounding, RotationPlace{7, ""});
  } catch (const InputError& error) {
    EXPECT_EQ(error.source(), "robot.csv");
    EXPECT_EQ(error.line(), 7);
    EXPECT_EQ(std::string(error.what()).find('\n'), std::string::npos);
    EXPECT_FALSE(error.fix().empty());
    return error;
  }
  ADD_FAILURE() << "accepted\n" << M;
  return InputError("", 0, "", "");
}

InputError QuaternionError(const Eigen::Vector4d& wxyz, double rounding = 0.0) {
  RotationInput input("robot.csv");
  try {
    input.Quaternion(wxyz, rounding, RotationPlace{3, ""}, "qw,qx,qy,qz");
  } catch (const InputError& error) {
    EXPECT_EQ(error.line(), 3);
    return error;
  }
  ADD_FAILURE() << "accepted " << wxyz.transpose();
  return InputError("", 0, "", "");
}

TEST(PrintedRounding, FollowsTheDigits) {
  EXPECT_DOUBLE_EQ(PrintedRounding("0.985976"), 5e-7);
  EXPECT_DOUBLE_EQ(PrintedRounding("-0.5"), 0.05);
  EXPECT_DOUBLE_EQ(PrintedRounding("+0.125"), 5e-4);
  EXPECT_DOUBLE_EQ(PrintedRounding("1.17359e-06"), 5e-12);
  EXPECT_DOUBLE_EQ(PrintedRounding("1.5E+2"), 5.0);
  EXPECT_DOUBLE_EQ(PrintedRounding("0.12345678901234567"), 5e-18);
  EXPECT_DOUBLE_EQ(PrintedRounding("1.5e-30"), 5e-32);  // beyond the table of powers
  // No fraction digits: exact (0, 1, OpenCV's "1.", 1e-5).
  EXPECT_EQ(PrintedRounding("1"), 0.0);
  EXPECT_EQ(PrintedRounding("1."), 0.0);
  EXPECT_EQ(PrintedRounding("1e-5"), 0.0);
  EXPECT_EQ(PrintedRounding("nan"), 0.0);
}

TEST(RotationInput, RoundingNoiseIsProjectedSilently) {
  // 2e-7 off: the nearest rotation is kR (polar decomposition), no note.
  const testing::NearlyOrthonormal noisy = ControllerMatrix(kR, 1e-7);
  RotationInput input("robot.csv");
  const Eigen::Matrix3d R = input.Matrix(noisy.matrix, 0.0, RotationPlace{2, ""});
  EXPECT_LT((R - kR).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_TRUE(input.Notes().empty());
}

TEST(RotationInput, ControllerMatricesAreProjectedWithOneNote) {
  // 2e-5 off, as a controller writes its own matrix with 17 digits; three rows, the worst at
  // line 12.
  RotationInput input("robot.csv");
  for (const auto& [size, line] : {std::pair{0.5e-5, 11}, {1e-5, 12}, {0.2e-5, 13}}) {
    const testing::NearlyOrthonormal m = ControllerMatrix(kR, size);
    EXPECT_LT((input.Matrix(m.matrix, 5e-17, RotationPlace{line, ""}) - kR).cwiseAbs().maxCoeff(),
              1e-15);
  }
  const std::vector<std::string> notes = input.Notes();
  ASSERT_EQ(notes.size(), 1u);
  // e = |P² − I| = 2·1e-5 + 1e-10 at the (0, 0) entry of P = I + 1e-5·S.
  EXPECT_THAT(notes[0], AllOf(HasSubstr("robot.csv: 3 of 3 rotation matrices were not orthonormal "
                                        "within 1e-6 (largest error 2.0e-05 at line 12)"),
                              HasSubstr("projected onto the nearest rotation"),
                              Not(HasSubstr("entries printed"))));
  // The largest change of an entry is |kR·(1e-5·S)| at its largest.
  const Eigen::Matrix3d change = ControllerMatrix(kR, 1e-5).matrix - kR;
  char expected[64];
  std::snprintf(expected, sizeof(expected), "largest change of an entry %.1e)",
                change.cwiseAbs().maxCoeff());
  EXPECT_THAT(notes[0], HasSubstr(expected));
}

TEST(RotationInput, NotesNameTheSubjectAndThePlace) {
  RotationInput input("pose_samples.json", "robot");
  input.Matrix(ControllerMatrix(kR, 1e-5).matrix, 0.0, RotationPlace{0, "sample 4 M_eef"});
  input.Matrix(kR, 0.0, RotationPlace{0, "sample 5 M_eef"});
  input.Quaternion(Eigen::Vector4d(1.0004, 0, 0, 0), 0.0, RotationPlace{9, "T1_2"}, "w, x, y, z");
  const std::vector<std::string> notes = input.Notes();
  ASSERT_EQ(notes.size(), 2u);
  EXPECT_THAT(notes[0], HasSubstr("pose_samples.json: 1 of 2 robot rotation matrices"));
  EXPECT_THAT(notes[0], HasSubstr("at sample 4 M_eef)"));
  EXPECT_THAT(notes[1], HasSubstr("pose_samples.json: 1 of 1 robot quaternions were not unit "
                                  "within 1e-6 (largest |norm - 1| 4.0e-04 at line 9 (T1_2)); "
                                  "normalised"));
}

TEST(RotationInput, TheToleranceIs1e3WidenedByThePrintedDigitsUpTo1e2) {
  // Diagonal scalings diag(1 + d, 1, 1): e = (1 + d)² − 1 ≈ 2d (not a uniform scale).
  const auto off_by = [](double e) {
    Eigen::Matrix3d M = Eigen::Matrix3d::Identity();
    M(0, 0) = std::sqrt(1.0 + e);
    return M;
  };
  RotationInput input("r.csv");
  EXPECT_NO_THROW(input.Matrix(off_by(0.99e-3), 0.0, {}));
  EXPECT_THAT(MatrixError(off_by(1.01e-3)).what(), HasSubstr("more than the 1.0e-03 allowed"));
  // 3 decimals (u = 5e-4): 6u = 3e-3.
  EXPECT_NO_THROW(input.Matrix(off_by(2.9e-3), 5e-4, {}));
  EXPECT_THAT(MatrixError(off_by(3.1e-3), 5e-4).what(),
              HasSubstr("more than the 3.0e-03 allowed for entries printed to +-5.0e-04"));
  // 2 decimals (u = 5e-3): 6u = 3e-2, capped at 1e-2.
  EXPECT_NO_THROW(input.Matrix(off_by(0.99e-2), 5e-3, {}));
  EXPECT_THAT(MatrixError(off_by(1.1e-2), 5e-3).what(), HasSubstr("1.0e-02 allowed"));
}

TEST(RotationInput, AReflectionIsCalledAReflection) {
  const Eigen::Matrix3d mirror = kR * Eigen::Vector3d(1, 1, -1).asDiagonal();
  const InputError error = MatrixError(mirror);
  EXPECT_THAT(error.problem(), HasSubstr("the rotation matrix is a reflection (det R = -1)"));
  EXPECT_THAT(error.problem(), Not(HasSubstr("orthonormal either")));
  EXPECT_THAT(error.fix(), HasSubstr("axis-sign"));
  EXPECT_THAT(error.what(), Not(HasSubstr("digits")));
  // Two columns swapped is a reflection too; a scaled reflection is not orthonormal either.
  Eigen::Matrix3d swapped = kR;
  swapped.col(0).swap(swapped.col(1));
  EXPECT_THAT(MatrixError(swapped).problem(), HasSubstr("reflection"));
  EXPECT_THAT(MatrixError(2.0 * mirror).problem(),
              HasSubstr("det R = -8), not a rotation, and not orthonormal either (singular "
                        "values 2, 2, 2)"));
}

TEST(RotationInput, AMatrixFarFromARotationGivesItsSingularValues) {
  // 1e-1 off: a shear, not a rounding problem and not a scale.
  Eigen::Matrix3d shear = kR;
  shear(0, 1) += 0.1;
  const InputError error = MatrixError(shear, 5e-7);
  EXPECT_THAT(error.problem(), HasSubstr("the rotation matrix is not orthonormal: "
                                         "max(|R^T R - I|, |det R - 1|) = "));
  EXPECT_THAT(error.problem(), HasSubstr("more than the 1.0e-03 allowed (singular values "));
  EXPECT_THAT(error.fix(), HasSubstr("row-major"));
  EXPECT_THAT(error.what(), Not(HasSubstr("digits")));
  // A translation in the 3×3 block (a misplaced entry).
  Eigen::Matrix3d misplaced = kR;
  misplaced(0, 0) = 512.3;
  EXPECT_THAT(MatrixError(misplaced, 5e-2).problem(), HasSubstr("not orthonormal"));
}

TEST(RotationInput, AScaledRotationNamesTheScale) {
  const InputError error = MatrixError(1.5 * kR);
  EXPECT_THAT(error.problem(),
              HasSubstr("is a rotation scaled by 1.5 (singular values 1.5, 1.5, 1.5)"));
  EXPECT_THAT(error.fix(), HasSubstr("divide the 3x3 block by 1.5"));
  EXPECT_THAT(MatrixError(1000.0 * kR).problem(), HasSubstr("scaled by 1000"));
}

TEST(RotationInput, OnlyCoarseDigitsAskForMoreDigits) {
  // Rz(0.3) printed with 1 decimal: e = 0.09 > 1e-2, within 6u = 0.3.
  Eigen::Matrix3d coarse;
  coarse << 1.0, -0.3, 0, 0.3, 1.0, 0, 0, 0, 1;
  const InputError error = MatrixError(coarse, 0.05);
  EXPECT_THAT(error.problem(), HasSubstr("printed too coarsely"));
  EXPECT_THAT(error.fix(), HasSubstr("more digits"));
  // The same matrix written exactly (u = 0) is simply not a rotation.
  EXPECT_THAT(MatrixError(coarse, 0.0).what(), Not(HasSubstr("digits")));
}

TEST(RotationInput, HugeAndZeroMatricesAreRefusedWithoutOverflow) {
  Eigen::Matrix3d huge;
  huge << 1e200, 1e200, 1e200, -1e200, 1e200, 1e200, 1, 1, 1;
  EXPECT_THAT(MatrixError(huge).problem(), HasSubstr("not orthonormal"));
  EXPECT_THAT(MatrixError(Eigen::Matrix3d::Zero()).problem(),
              HasSubstr("(singular values 0, 0, 0)"));
}

TEST(RotationInput, Quaternions) {
  RotationInput input("robot.csv");
  // Norm 1.0004: normalised, with a note.
  const Eigen::Matrix3d R =
      input.Quaternion(Eigen::Vector4d(1.0004 * std::cos(0.2), 0, 0, 1.0004 * std::sin(0.2)), 0.0,
                       RotationPlace{5, ""}, "qw,qx,qy,qz");
  EXPECT_LT((R - Rz(0.4)).cwiseAbs().maxCoeff(), 1e-15);
  // 6-digit quaternions are rounding noise: silent.
  input.Quaternion(Eigen::Vector4d(0.707107, 0, 0, 0.707107), 5e-7, RotationPlace{6, ""}, "");
  const std::vector<std::string> notes = input.Notes();
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_THAT(notes[0], HasSubstr("robot.csv: 1 of 2 quaternions were not unit within 1e-6 "
                                  "(largest |norm - 1| 4.0e-04 at line 5); normalised"));

  // Norm 1.5 (and 1.73: three ones and a zero) are not unit quaternions.
  const InputError far = QuaternionError(Eigen::Vector4d(1.5, 0, 0, 0));
  EXPECT_THAT(far.problem(), HasSubstr("quaternion norm 1.5, not 1"));
  EXPECT_THAT(far.problem(), HasSubstr("not a unit quaternion"));
  EXPECT_THAT(far.fix(), HasSubstr("are qw,qx,qy,qz a quaternion, in that order?"));
  EXPECT_THAT(QuaternionError(Eigen::Vector4d(1, 1, 1, 0)).problem(),
              HasSubstr("quaternion norm 1.73205, not 1"));
  EXPECT_THAT(QuaternionError(Eigen::Vector4d(1.0011, 0, 0, 0)).problem(),
              HasSubstr("more than the 1.0e-03 allowed"));
  // Zero, and too small to be anything but zero; huge components do not overflow the norm.
  EXPECT_THAT(QuaternionError(Eigen::Vector4d::Zero()).problem(), HasSubstr("zero quaternion"));
  EXPECT_THAT(QuaternionError(Eigen::Vector4d(0, 0, 0, 1e-300)).problem(),
              HasSubstr("zero quaternion"));
  EXPECT_THAT(QuaternionError(Eigen::Vector4d(1e300, 0, 0, 1e300)).problem(),
              HasSubstr("quaternion norm 1.41421e+300"));
  // 1 decimal: "0.7, 0, 0, 0.7" has norm 0.98995, off by more than 1e-2 only through its digits.
  const InputError coarse = QuaternionError(Eigen::Vector4d(0.7, 0, 0, 0.7), 0.05);
  EXPECT_THAT(coarse.problem(), HasSubstr("printed too coarsely"));
  EXPECT_THAT(coarse.fix(), HasSubstr("more digits"));
  // 3 decimals widen the tolerance to 3u = 1.5e-3.
  EXPECT_NO_THROW(input.Quaternion(Eigen::Vector4d(1.0014, 0, 0, 0), 5e-4, {}, ""));
}

}  // namespace
}  // namespace hecal::io
