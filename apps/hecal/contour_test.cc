// `hecal contour pose` and `hecal contour study` as docs/cli.md states them:
// flags, JSON fields, CSV columns, plots, and bad input (exit 2, one line, no file written).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <numbers>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "cli_test_util.h"
#include "hecal/contour/affine_pose.h"
#include "hecal/contour/perspective_view.h"

namespace hecal::cli {
namespace {

using cli_test::CliTest;
using cli_test::Hecal;

std::string ShapeFlag(const Vector6d& S) {
  std::ostringstream out;
  out.precision(17);
  for (int i = 0; i < 6; ++i) out << (i ? "," : "") << S(i);
  return out.str();
}

TEST(ContourPoseCommand, JsonRecoversAKnownMotion) {
  // The paper's setting in mm: f = 50, Z0 = 5000; a combined motion inside the zyx ranges.
  const contour::ContourCamera camera{50.0, 5000.0};
  const Eigen::Matrix3d R = contour::RotationZyx(0.3, 0.2, 1.1);
  const Eigen::Vector3d T(120.0, -80.0, -900.0);
  const Vector6d S = contour::ShapeFromPose(R, T, camera);
  const auto run = Hecal(
      {"contour", "pose", "--shape=" + ShapeFlag(S), "--z0", "5000", "--focal", "50", "--json"});
  ASSERT_EQ(run.code, 0) << run.err;
  const nlohmann::json j = nlohmann::json::parse(run.out);
  EXPECT_EQ(j["sequence"], "ZYX");
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(j["translation"][i].get<double>(), T(i), 1e-8);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(j["rotation_matrix"][i][c].get<double>(), R(i, c), 1e-12);
    }
  }
  EXPECT_NEAR(j["euler"][0].get<double>(), 1.1, 1e-12);  // (Rz, Ry, Rx), radians
  EXPECT_NEAR(j["euler"][1].get<double>(), 0.2, 1e-12);
  EXPECT_NEAR(j["euler"][2].get<double>(), 0.3, 1e-12);
  EXPECT_NEAR(j["euler_deg"][2].get<double>(), 0.3 * 180 / std::numbers::pi, 1e-10);
  // zxz: the same affinity, the ZXZ angles.
  const auto zxz = Hecal({"contour", "pose", "--shape=" + ShapeFlag(S), "--z0", "5000", "--focal",
                          "50", "--rotation", "zxz", "--json"});
  ASSERT_EQ(zxz.code, 0) << zxz.err;
  EXPECT_EQ(nlohmann::json::parse(zxz.out)["sequence"], "ZXZ");
}

TEST(ContourPoseCommand, CovarianceGivesTheUnscentedPose) {
  const auto run =
      Hecal({"contour", "pose", "--shape", "1,2,0.01,-0.05,0.002,-0.001", "--z0", "5000", "--focal",
             "6024", "--covariance", "0.04,0.04,1e-6,1e-6,1e-6,1e-6", "--json"});
  ASSERT_EQ(run.code, 0) << run.err;
  const nlohmann::json j = nlohmann::json::parse(run.out);
  ASSERT_EQ(j["covariance"].size(), 6u);
  EXPECT_GT(j["covariance"][0][0].get<double>(), 0.0);
  EXPECT_EQ(j["parameters"][3], "Rx");
  EXPECT_TRUE(j["bias"].contains("Rz"));
  const auto text =
      Hecal({"contour", "pose", "--shape", "1,2,0.01,-0.05,0.002,-0.001", "--z0", "5000", "--focal",
             "6024", "--covariance", "0.04,0.04,1e-6,1e-6,1e-6,1e-6"});
  EXPECT_NE(text.out.find("UT (13 sigma points)"), std::string::npos) << text.out;
}

TEST(ContourPoseCommand, BadInputExitsTwoWithOneLine) {
  const std::vector<std::vector<std::string>> cases = {
      {"--shape", "0,0,0,-1,0,0", "--z0", "5000", "--focal", "50"},  // singular M (edge-on)
      {"--shape", "0,0,0,-2,0,0", "--z0", "5000", "--focal", "50"},  // reflection
      {"--shape", "0,0,0,0,0", "--z0", "5000", "--focal", "50"},     // five numbers
      {"--shape", "0,0,x,0,0,0", "--z0", "5000", "--focal", "50"},   // not a number
      {"--shape", "0,0,0,0,0,0", "--z0", "-5", "--focal", "50"},     // Z0 ≤ 0
      {"--shape", "0,0,0,0,0,0", "--z0", "5000", "--focal", "50", "--rotation", "xyz"},
      {"--shape", "0,0,0,0,0,0", "--z0", "5000", "--focal", "50", "--covariance", "1,2,3"},
      {"--shape", "0,0,0,0,0,0", "--z0", "5000", "--focal", "50", "--covariance", "-1,1,1,1,1,1"},
  };
  for (const std::vector<std::string>& flags : cases) {
    std::vector<std::string> args = {"contour", "pose"};
    args.insert(args.end(), flags.begin(), flags.end());
    const auto run = Hecal(args);
    EXPECT_EQ(run.code, 2) << flags[1];
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_TRUE(run.out.empty()) << run.out;
  }
}

class ContourStudyCommand : public CliTest {};

TEST_F(ContourStudyCommand, WritesTheCsvOfTheContractAndThePage) {
  const auto run = Hecal({"contour", "study", "--motion", "rx", "--from", "0", "--to", "20",
                          "--steps", "3", "--samples", "2000", "--output", Path("rx.csv"),
                          "--report", Path("rx.html"), "--covariance-at", "20"});
  ASSERT_EQ(run.code, 0) << run.err;
  std::istringstream csv(Read("rx.csv"));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "# hecal contour study: seed 1, 2000 Monte Carlo samples per step");
  std::getline(csv, line);
  EXPECT_EQ(line, "motion,value,component,mc_mean_error,mc_std,ut_mean_error,ut_std,bias");
  std::vector<std::string> rows;
  while (std::getline(csv, line)) rows.push_back(line);
  ASSERT_EQ(rows.size(), 18u);  // 3 steps × 6 components
  EXPECT_EQ(rows[3].rfind("rx,0,Rx,", 0), 0u) << rows[3];
  EXPECT_EQ(rows[3].back(), '1');  // zero tilt: the bias flag
  EXPECT_EQ(rows[15].rfind("rx,20,Rx,", 0), 0u) << rows[15];
  EXPECT_EQ(rows[15].back(), '0');
  // Degrees: at 20° the Rx standard deviation is a fraction of a degree, not of a radian.
  std::istringstream fields(rows[15]);
  std::string field;
  for (int i = 0; i < 5; ++i) std::getline(fields, field, ',');
  EXPECT_GT(std::stod(field), 0.1);
  EXPECT_LT(std::stod(field), 2.0);
  const std::string page = Read("rx.html");
  EXPECT_NE(page.find("\"kind\":\"contour_study\""), std::string::npos);
  EXPECT_NE(page.find("\"covariance\":{\"mc_covariance\""), std::string::npos);
  EXPECT_NE(page.find("\"value\":20.0}"), std::string::npos);  // Fig. 4 at --covariance-at
  EXPECT_FALSE(std::filesystem::exists(Path("rx.svg")));       // no hand-drawn figure any more
  EXPECT_NE(run.out.find("largest |correlation|"), std::string::npos);
}

// Whether two texts are equal but for their numbers, each within a relative 1e-6 (or 1e-12):
// the unscented transform of a near-singular step moves the last printed digits between builds.
bool SameTextAndNumbers(const std::string& a, const std::string& b) {
  const std::regex number(R"([-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?)");
  std::sregex_token_iterator ia(a.begin(), a.end(), number, {-1, 0}),
      ib(b.begin(), b.end(), number, {-1, 0}), end;
  for (bool is_number = false; ia != end && ib != end; ++ia, ++ib, is_number = !is_number) {
    if (!is_number) {
      if (ia->str() != ib->str()) return false;
      continue;
    }
    const double x = std::stod(ia->str()), y = std::stod(ib->str());
    if (std::abs(x - y) > 1e-6 * std::max(std::abs(x), std::abs(y)) + 1e-12) return false;
  }
  return ia == end && ib == end;
}

// The study files docs/contour/ shows are what its commands write: each `hecal contour study`
// line of docs/contour.md's command block is run with its docs/contour/ and out/contour/ paths
// moved into the test folder, and every CSV it writes to docs/contour/ equals the one in the
// repository (SameTextAndNumbers). The pages (out/contour/) are what scripts/docs-figures.sh
// screenshots into docs/contour/*.png.
TEST_F(ContourStudyCommand, DocumentedFilesAreWhatTheirCommandsWrite) {
  const std::filesystem::path root = HECAL_SOURCE_DIR;
  std::istringstream page(io::ReadFile((root / "docs" / "contour.md").string()));
  std::vector<std::string> commands;
  std::string line, command;
  while (std::getline(page, line)) {
    const bool continued = !line.empty() && line.back() == '\\';
    if (continued) line.pop_back();
    command += line;
    if (continued) continue;
    if (command.rfind("hecal contour study ", 0) == 0) commands.push_back(command);
    command.clear();
  }
  ASSERT_GE(commands.size(), 7u);
  const std::string prefix = "docs/contour/", pages = "out/contour/";
  int compared = 0;
  for (const std::string& documented : commands) {
    std::istringstream words(documented.substr(std::string("hecal ").size()));
    std::vector<std::string> args, written;
    for (std::string word; words >> word;) {
      if (word.rfind(prefix, 0) == 0) {
        written.push_back(word.substr(prefix.size()));
        word = Path(written.back());
      } else if (word.rfind(pages, 0) == 0) {
        word = Path(word.substr(pages.size()));
      }
      args.push_back(word);
    }
    const auto run = Hecal(args);
    ASSERT_EQ(run.code, 0) << documented << "\n" << run.err;
    for (const std::string& name : written) {
      EXPECT_TRUE(
          SameTextAndNumbers(Read(name), io::ReadFile((root / "docs" / "contour" / name).string())))
          << "docs/contour/" << name << " differs from what `" << documented << "` writes";
      ++compared;
    }
  }
  EXPECT_GE(compared, 6);  // the six CSVs
}

TEST_F(ContourStudyCommand, ReadsAContourAndRejectsBadOnesWithoutWriting) {
  Write("target.csv", "# a square-ish target, mm\nx,y\n-100,-80\n100,-70\n90,80\n-95,75\n");
  const auto ok =
      Hecal({"contour", "study", "--motion", "tz", "--from", "0", "--to", "-1000", "--steps", "2",
             "--samples", "200", "--contour", Path("target.csv"), "--output", Path("ok.csv")});
  EXPECT_EQ(ok.code, 0) << ok.err;
  Write("line.csv", "x,y\n0,0\n1,1\n2,2\n3,3\n4,4\n");
  Write("bad.csv", "x,y\n0,0\n1,abc\n2,2\n3,3\n");
  Write("short.csv", "x,y\n0,0\n1,1\n");
  const std::vector<std::string> tz = {"--motion", "tz",      "--from", "0",         "--to",
                                       "-1000",    "--steps", "2",      "--samples", "100"};
  const auto with = [&](std::vector<std::string> flags) {
    flags.insert(flags.begin(), tz.begin(), tz.end());
    return flags;
  };
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {with({"--contour", Path("line.csv")}), "collinear"},
      {with({"--contour", Path("bad.csv")}), "bad.csv:3:"},
      {with({"--contour", Path("short.csv")}), "at least 4"},
      {with({"--contour", Path("missing.csv")}), "missing.csv"},
      {{"--motion", "rx", "--from", "0", "--to", "95", "--steps", "2"}, "90°"},
      {{"--motion", "spin", "--from", "0", "--to", "1", "--steps", "2"}, "unknown motion"},
      {{"--motion", "tz", "--from", "0", "--to", "-1000", "--steps", "1"}, "--steps"},
  };
  for (const auto& [flags, expected] : cases) {
    std::vector<std::string> args = {"contour", "study"};
    args.insert(args.end(), flags.begin(), flags.end());
    args.insert(args.end(), {"--output", Path("out.csv")});
    const auto run = Hecal(args);
    EXPECT_EQ(run.code, 2) << expected;
    EXPECT_NE(run.err.find(expected), std::string::npos) << run.err;
    EXPECT_FALSE(std::filesystem::exists(Path("out.csv"))) << expected;
  }
}

}  // namespace
}  // namespace hecal::cli
