// `hecal pivot` and `hecal simulate --pivot` through RunHecal: a synthetic pivot calibrated back,
// bad and degenerate files refused with exit 2 and nothing written.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_test_util.h"

namespace hecal::cli {
namespace {

using cli_test::Hecal;
using cli_test::Outcome;
using PivotCommand = cli_test::CliTest;

// The file `simulate --pivot --write-pivot` writes is trial 0 of jobs::PivotStudyTrial: the truth
// comes from the simulator, not from the fit.
TEST_F(PivotCommand, SyntheticFileCalibratesBack) {
  const Outcome simulate =
      Hecal({"simulate", "--pivot", "--trials", "3", "--stations", "20", "--sigma", "0.1", "--seed",
             "5", "--write-pivot", Path("poses.csv")});
  ASSERT_EQ(simulate.code, 0) << simulate.err;
  EXPECT_NE(simulate.out.find("mean NEES"), std::string::npos) << simulate.out;
  jobs::PivotStudyOptions study;
  study.seed = 5;
  const sim::PivotScene truth = jobs::PivotStudyTrial(study, {0.1, 0.1}, 20, 0);

  for (const std::string& output : {std::string("pivot.json"), std::string("pivot.yaml")}) {
    const Outcome run = Hecal({"pivot", "--robot", Path("poses.csv"), "--robot-sigma", "0.1,0.1",
                               "--output", Path(output)});
    ASSERT_EQ(run.code, 0) << run.err;
    EXPECT_NE(run.out.find("tip in flange:"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("20 of 20 used, 0 flagged"), std::string::npos) << run.out;
    if (output == "pivot.yaml") {
      EXPECT_NE(Read(output).find("kind: pivot"), std::string::npos);
      continue;
    }
    const nlohmann::json doc = nlohmann::json::parse(Read(output));
    EXPECT_EQ(doc["units"]["length"], "mm");  // the file's unit
    EXPECT_EQ(doc["noise"]["estimated"], false);
    for (int k = 0; k < 3; ++k) {
      const double tip = doc["tip"]["translation"][k], tip_sigma = doc["tip"]["sigma"][k];
      const double pivot = doc["pivot"]["translation"][k], pivot_sigma = doc["pivot"]["sigma"][k];
      EXPECT_LT(std::abs(tip - truth.tip(k) * 1e3), 4 * tip_sigma) << k;
      EXPECT_LT(std::abs(pivot - truth.pivot(k) * 1e3), 4 * pivot_sigma) << k;
      EXPECT_GT(tip_sigma, 0.0);
      EXPECT_LT(tip_sigma, 1.0);  // mm
    }
    EXPECT_EQ(doc["residuals"]["per_station"].size(), 20u);
    EXPECT_EQ(doc["residuals"]["per_station"][0]["id"], "1");
    EXPECT_EQ(doc["covariance"]["matrix"].size(), 6u);
  }
  // Without --robot-sigma the noise is estimated and said so.
  const Outcome estimated = Hecal({"pivot", "--robot", Path("poses.csv")});
  ASSERT_EQ(estimated.code, 0) << estimated.err;
  EXPECT_NE(estimated.out.find("(estimated)"), std::string::npos) << estimated.out;
}

TEST_F(PivotCommand, BadFileExitsTwoWithTheLine) {
  const std::string file = Write("bad.csv",
                                 "x_mm,y_mm,z_mm,qw,qx,qy,qz\n"
                                 "600,0,300,0,1,0,0\n"
                                 "600,0,abc,0,1,0,0\n");
  ExpectRefused({"pivot", "--robot", file, "--output", Path("out.json")}, file + ":3",
                "not a number", "out.json");
}

TEST_F(PivotCommand, DegenerateExitsTwoNamingTheComponent) {
  // The flange spins about its own z axis only, tip 150 mm along z: the tip's z and the pivot's
  // height are not observable.
  std::string text = "x_mm,y_mm,z_mm,rx_deg,ry_deg,rz_deg\n";
  for (int i = 0; i < 10; ++i) {
    const double angle = -60.0 + 12.0 * i;
    text += "600,0,450,0,0," + std::to_string(angle) + "\n";
  }
  const std::string file = Write("spin.csv", text);
  const Outcome run = Hecal({"pivot", "--robot", file, "--output", Path("out.json")});
  EXPECT_EQ(run.code, 2) << run.err;
  EXPECT_EQ(run.err.rfind("hecal: degenerate data: cannot observe the tip offset along the "
                          "flange axis (",
                          0),
            0u)
      << run.err;
  EXPECT_NE(run.err.find("tilt the tool about a second axis"), std::string::npos) << run.err;
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  EXPECT_TRUE(run.out.empty()) << run.out;
  EXPECT_FALSE(std::filesystem::exists(Path("out.json")));
}

TEST_F(PivotCommand, BadFlagsNameTheFlag) {
  const std::string file = Write("p.csv", "x,y,z,qw,qx,qy,qz\n0.6,0,0.3,0,1,0,0\n");
  ExpectRefused({"pivot", "--robot", file, "--robot-sigma", "0,0.1", "--output", Path("o.json")},
                "--robot-sigma", "translation noise must be above 0", "o.json");
  ExpectRefused({"simulate", "--pivot", "--sigma", "0"}, "--sigma", "0 < mm", "o.json");
  ExpectRefused({"simulate", "--pivot", "--report", Path("o.json")}, "--report",
                "does not apply to the pivot study", "o.json");
}

TEST_F(PivotCommand, HelpFitsOnAScreen) {
  const Outcome help = Hecal({"pivot", "--help"});
  ASSERT_EQ(help.code, 0);
  EXPECT_LE(std::count(help.out.begin(), help.out.end(), '\n'), 40) << help.out;
}

}  // namespace
}  // namespace hecal::cli
