// The command line's own syntax rules (bounds.h), driven through `hecal`: a whole number is
// decimal digits (CLI11 alone would read "010" as octal and "-1" as 2^64 − 1 for a seed), a
// whole-number list has no empty item, a noise level is two numbers (or one where a single level
// is allowed), a sweep of finite numbers takes any count of them. A bad value exits 2 with one
// line naming the flag and the text, before any work.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "cli_test_util.h"

namespace hecal::cli {
namespace {

using cli_test::Hecal;
using cli_test::Outcome;

class Bounds : public cli_test::CliTest {
 protected:
  // Exit 2, one line `hecal: FLAG: PROBLEM…`, nothing on stdout.
  static void ExpectRefused(const std::vector<std::string>& args, const std::string& flag,
                            const std::string& problem) {
    const Outcome run = Hecal(args);
    EXPECT_EQ(run.code, 2) << run.err;
    EXPECT_EQ(run.err.rfind("hecal: " + flag + ": " + problem, 0), 0u) << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_TRUE(run.out.empty()) << run.out;
  }

  std::vector<std::string> Simulate(std::vector<std::string> extra) const {
    std::vector<std::string> args = {"simulate",  "--method", "andreff",  "--trials",        "1",
                                     "--threads", "1",        "--output", Path("trials.csv")};
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
  }
};

TEST_F(Bounds, WholeNumbersAreDecimal) {
  // A leading zero is still decimal: 010 stations are ten, not eight.
  const Outcome run = Hecal(Simulate({"--stations", "010"}));
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_NE(run.out.find("eye-in-hand, 10 stations"), std::string::npos) << run.out;

  const std::string not_decimal = "must be a whole number in decimal digits, got ";
  ExpectRefused(Simulate({"--threads", "0x10"}), "--threads", not_decimal + "'0x10'");
  ExpectRefused(Simulate({"--trials", "1e3"}), "--trials", not_decimal + "'1e3'");
  ExpectRefused(Simulate({"--covariance-samples", "2.5"}), "--covariance-samples",
                not_decimal + "'2.5'");
  ExpectRefused({"contour", "study", "--motion", "tx", "--from", "0", "--to", "1", "--steps", "x",
                 "--output", Path("study.csv")},
                "--steps", not_decimal + "'x'");
  ExpectRefused({"bench", "--datasets", "99999999999"}, "--datasets",
                "must be a whole number from -2147483648 to 2147483647, got '99999999999'");
}

TEST_F(Bounds, SeedsAreUnsignedDecimal) {
  const std::string range = "must be a whole number from 0 to 18446744073709551615, got ";
  ExpectRefused(Simulate({"--seed", "-1"}), "--seed", range + "'-1'");
  ExpectRefused(Simulate({"--seed", "18446744073709551616"}), "--seed",
                range + "'18446744073709551616'");
  ExpectRefused({"bench", "--seed", "0x1"}, "--seed", range + "'0x1'");
  ExpectRefused({"calibrate", "--robot", Path("r.csv"), "--camera", Path("c.csv"), "--setup",
                 "eye-in-hand", "--seed", "1.0"},
                "--seed", range + "'1.0'");
}

TEST_F(Bounds, WholeNumberListsHaveNoEmptyItem) {
  ExpectRefused(Simulate({"--stations", "5,,6"}), "--stations", "empty item in the list '5,,6'");
  ExpectRefused(Simulate({"--outliers", "0,x"}), "--outliers",
                "must be a whole number in decimal digits, got 'x'");
}

TEST_F(Bounds, NoiseLevelsAreTwoNumbers) {
  ExpectRefused({"calibrate", "--robot", Path("r.csv"), "--camera", Path("c.csv"), "--setup",
                 "eye-in-hand", "--robot-sigma", "0.5"},
                "--robot-sigma", "expected two numbers MM,DEG, got '0.5'");
  ExpectRefused(Simulate({"--sigma", "0.3,1/x"}), "--sigma",
                "expected two numbers MM/DEG or one number N, got '1/x'");
  ExpectRefused({"bench", "--sigma", "nan"}, "--sigma",
                "expected two numbers MM/DEG or one number N, got 'nan'");
  // A negative level is a number; its range is the options' (jobs::SimulateOptions::IsValid).
  ExpectRefused(Simulate({"--sigma", "-1"}), "--sigma", "noise levels must be 0 to 1000 mm");
}

TEST_F(Bounds, NumberSweepsTakeAnyCountOfFiniteNumbers) {
  // Items are trimmed; one setting per value, in the given order.
  const Outcome run = Hecal(Simulate({"--stations", "3", "--sigma", "0.1", "--robot-scale",
                                      " 1, 2.5", "--summary", Path("summary.csv")}));
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_EQ(run.out.find("robot noise 1x"), std::string::npos) << run.out;  // the plain setting
  EXPECT_NE(run.out.find("1 trials, robot noise 2.5x"), std::string::npos) << run.out;
  ExpectRefused(Simulate({"--robot-scale", "1,,2"}), "--robot-scale",
                "'' is not a finite number (in '1,,2')");
  ExpectRefused(Simulate({"--robot-scale", "0x1"}), "--robot-scale",
                "'0x1' is not a finite number (in '0x1')");
}

}  // namespace
}  // namespace hecal::cli
