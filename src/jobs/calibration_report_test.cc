#include "hecal/jobs/calibration_report.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "hecal/core/error.h"
#include "hecal/geometry/se3.h"

namespace hecal::jobs {
namespace {

namespace fs = std::filesystem;

std::string Slurp(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Two image stations ("im_a", "im_b") and the robot table in their order, without ids (as
// `calibrate --images` reads it): the page gets both poses, in millimetres.
TEST(CalibrationReport, MatchesImageStationsToRowsInOrder) {
  const fs::path dir = fs::temp_directory_path() / "hecal_calibration_report_test";
  fs::create_directories(dir);
  std::ofstream(dir / "robot.csv") << "x,y,z,qw,qx,qy,qz\n0.1,0,0,1,0,0,0\n0.2,0,0,1,0,0,0\n";
  report::ResultDocument document;
  document.unit = io::LengthUnit::kMillimetre;
  document.station_ids = {"im_a", "im_b"};
  estimation::CalibrationResult result;
  result.X = se3::Exp((Vector6d() << 0.1, 0.2, -0.3, 0.01, -0.02, 0.05).finished());
  result.Z = Pose::Identity();
  result.residuals = {{0.01, 0.002, 0.9, false}, {0.02, 0.004, 1.1, false}};
  document.results = {result};
  CalibrationReportOptions options;
  options.output = (dir / "page.html").string();
  options.robot = (dir / "robot.csv").string();
  WriteCalibrationReport(document, "test", options);
  const std::string page = Slurp(dir / "page.html");
  EXPECT_NE(page.find("\"robot_lines\":[2,3]"), std::string::npos);
  EXPECT_NE(page.find("[[1.0,0.0,0.0,200.0]"), std::string::npos);  // the second pose, in mm

  // A result file of other stations than the table's: refused, nothing written.
  fs::remove(dir / "page.html");
  report::WriteResult((dir / "r.json").string(), document);
  options.result = (dir / "r.json").string();
  EXPECT_THROW(WriteCalibrationReport(options), InputError);  // rows are "0", "1" here
  EXPECT_FALSE(fs::exists(dir / "page.html"));
  options.robot.clear();
  WriteCalibrationReport(options);
  EXPECT_TRUE(fs::exists(dir / "page.html"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace hecal::jobs
