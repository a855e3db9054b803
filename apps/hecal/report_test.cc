// `hecal report` on real data and on bad input (docs/cli.md#hecal-report, docs/report.md).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli_test_util.h"

namespace hecal::cli {
namespace {

using cli_test::Hecal;
namespace fs = std::filesystem;

TEST(ReportCommand, WritesThePageOfACalibration) {
  const fs::path dir = fs::temp_directory_path() / "hecal_report_test";
  fs::create_directories(dir);
  const std::string robot = (dir / "robot.csv").string(), camera = (dir / "camera.csv").string();
  const std::string result = (dir / "r.json").string(), page = (dir / "r.html").string();
  ASSERT_EQ(Hecal({"import", "--format", "moveit",
                   std::string(HECAL_SOURCE_DIR) + "/data/moveit-calibration/pose_samples.json",
                   "--robot", robot, "--camera", camera}).code, 0);
  ASSERT_EQ(Hecal({"calibrate", "--robot", robot, "--camera", camera, "--setup", "eye-to-hand",
                   "--output", result}).code, 0);
  const auto run = Hecal({"report", result, "--robot", robot, "--output", page});
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_GT(fs::file_size(page), 4'000'000u);  // Plotly.js inside
  std::ifstream in(page);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("\"robot_lines\":[9,"), std::string::npos);  // the scene's poses

  // A foreign JSON: exit 2, the field named, nothing written.
  const std::string foreign = (dir / "foreign.json").string();
  std::ofstream(foreign) << R"({"hecal_version": "x", "setup": "eye-to-hand", "method": "ml", "units": {"length": "km"}})";
  fs::remove(dir / "foreign.html");
  const auto bad = Hecal({"report", foreign, "--output", (dir / "foreign.html").string()});
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("field units.length: expected m or mm"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(dir / "foreign.html"));
  // The robot table of another calibration: its stations are not those of the result.
  std::ofstream(dir / "other.csv") << "id,x,y,z,qw,qx,qy,qz\nq,0,0,0,1,0,0,0\n";
  const auto other = Hecal({"report", result, "--robot", (dir / "other.csv").string(),
                            "--output", (dir / "other.html").string()});
  EXPECT_EQ(other.code, 2);
  EXPECT_NE(other.err.find("is not in this table"), std::string::npos) << other.err;
  EXPECT_FALSE(fs::exists(dir / "other.html"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace hecal::cli
