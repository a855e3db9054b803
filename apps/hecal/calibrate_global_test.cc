// `hecal calibrate --method global` end to end on a synthetic target-free scene written as a
// robot file and a correspondence file (bearings, and pixels with intrinsics), and its refusals
// (exit 2, one line, no result file).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli_test_util.h"
#include "testing/epipolar_scenes.h"
#include "testing/pose_csv.h"

namespace hecal::cli {
namespace {

using cli_test::CliTest;
using cli_test::Hecal;

class CalibrateGlobal : public CliTest {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    testing::EpipolarSceneSpec spec;
    spec.motions = 4;
    spec.pairs = 20;
    WriteScene(testing::MakeEpipolarScene(spec, 12));
  }

  // The scene as robot.csv, bearings.csv, pixels.csv and camera.yaml.
  void WriteScene(const testing::EpipolarScene& scene) {
    scene_ = scene;
    Write("robot.csv", testing::PoseCsv(scene_.T_base_gripper));
    std::ostringstream bearings, pixels;
    bearings.precision(17);
    pixels.precision(17);
    bearings << "first,second,id,x1,y1,z1,x2,y2,z2\n";
    pixels << "# pixels of a 1000 px pinhole camera centred at (320, 240)\n"
           << "first,second,id,u1,v1,u2,v2\n";
    for (const global::EpipolarMotion& motion : scene_.problem.motions) {
      for (const global::BearingPair& pair : motion.pairs) {
        const Eigen::Vector3d& v = pair.first;
        const Eigen::Vector3d& u = pair.second;
        bearings << "s" << motion.first_station << ",s" << motion.second_station << "," << pair.id
                 << "," << v.x() << "," << v.y() << "," << v.z() << "," << u.x() << "," << u.y()
                 << "," << u.z() << "\n";
        pixels << "s" << motion.first_station << ",s" << motion.second_station << "," << pair.id
               << "," << 320 + 1000 * v.x() / v.z() << "," << 240 + 1000 * v.y() / v.z() << ","
               << 320 + 1000 * u.x() / u.z() << "," << 240 + 1000 * u.y() / u.z() << "\n";
      }
    }
    Write("bearings.csv", bearings.str());
    Write("pixels.csv", pixels.str());
    Write("camera.yaml",
          "fx: 1000\nfy: 1000\ncx: 320\ncy: 240\nwidth: 640\nheight: 480\n"
          "distortion: {model: plumb_bob, coefficients: [0, 0, 0, 0, 0]}\n");
  }

  void ExpectSolved(const std::vector<std::string>& extra) {
    std::vector<std::string> args = {
        "calibrate", "--method",    "global",        "--robot", Path("robot.csv"),
        "--setup",   "eye-in-hand", "--epsilon",     "1e-5",    "--reach",
        "1",         "--output",    Path("out.json")};
    args.insert(args.end(), extra.begin(), extra.end());
    const auto result = Hecal(args);
    ASSERT_EQ(result.code, 0) << result.err;
    const nlohmann::json doc = nlohmann::json::parse(Read("out.json"));
    for (const char* key : {"lower", "upper", "cubes", "lps", "seconds"}) {
      EXPECT_TRUE(doc["certificate"].contains(key)) << key;
    }
    EXPECT_LE(doc["certificate"]["upper"].get<double>() - doc["certificate"]["lower"].get<double>(),
              1e-5);
    EXPECT_EQ(doc["certificate"]["epsilon"].get<double>(), 1e-5);
    EXPECT_EQ(doc["matches"]["inliers"].get<int>(), 80);
    EXPECT_TRUE(doc["matches"]["removed"].empty());
    Eigen::Matrix3d R;
    Eigen::Vector3d t;
    for (int r = 0; r < 3; ++r) {
      t[r] = doc["X"]["translation_m"][r].get<double>();
      for (int c = 0; c < 3; ++c) R(r, c) = doc["X"]["rotation"][r][c].get<double>();
    }
    EXPECT_LT(Eigen::AngleAxisd(R.transpose() * scene_.X.linear()).angle(), 1e-6);
    EXPECT_LT((t - scene_.X.translation()).norm(), 1e-6);
    EXPECT_EQ(doc["covariance"]["X"].size(), 6u);
    ASSERT_EQ(doc["motions"].size(), 4u);  // noise-free: every motion fits to rounding
    for (const nlohmann::json& motion : doc["motions"]) {
      EXPECT_EQ(motion["pairs"].get<int>(), 20);
      EXPECT_LT(motion["max_rad"].get<double>(), 1e-6);
    }
  }

  testing::EpipolarScene scene_;
};

TEST_F(CalibrateGlobal, RecoversXFromBearingsAndFromPixelsWithACertificate) {
  ExpectSolved({"--correspondences", Path("bearings.csv")});
  ExpectSolved({"--correspondences", Path("pixels.csv"), "--intrinsics", Path("camera.yaml")});
}

void ExpectRefusal(const cli_test::Outcome& result, const std::string& words) {
  EXPECT_EQ(result.code, 2) << result.out;
  EXPECT_NE(result.err.find(words), std::string::npos) << result.err;
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
}

// --report writes the global page beside the result file (both or neither); `hecal report` on
// the result file writes the same kind of page, and refuses a robot table (no scene to show) and
// an image folder (no images).
TEST_F(CalibrateGlobal, ReportPageFromTheRunAndFromTheResultFile) {
  const std::vector<std::string> args = {
      "calibrate",   "--method", "global", "--robot",           Path("robot.csv"),   "--setup",
      "eye-in-hand", "--reach",  "1",      "--correspondences", Path("bearings.csv")};
  std::vector<std::string> both = args, missing = args;
  both.insert(both.end(), {"--output", Path("g.json"), "--report", Path("g.html")});
  const auto run = Hecal(both);
  ASSERT_EQ(run.code, 0) << run.err;
  const std::string page = Read("g.html");
  EXPECT_NE(page.find("\"kind\":\"global\""), std::string::npos);
  EXPECT_NE(page.find("\"motions\":[{"), std::string::npos);
  EXPECT_NE(run.out.find("wrote " + Path("g.html")), std::string::npos) << run.out;
  const auto report = Hecal({"report", Path("g.json"), "--output", Path("again.html")});
  ASSERT_EQ(report.code, 0) << report.err;
  EXPECT_NE(Read("again.html").find("\"kind\":\"global\""), std::string::npos);
  ExpectRefusal(Hecal({"report", Path("g.json"), "--robot", Path("robot.csv"), "--output",
                       Path("scene.html")}),
                "no robot scene");
  EXPECT_FALSE(std::filesystem::exists(Path("scene.html")));
  ExpectRefusal(
      Hecal({"report", Path("g.json"), "--images", Path("."), "--output", Path("images.html")}),
      "not from images");
  EXPECT_FALSE(std::filesystem::exists(Path("images.html")));
  missing.insert(missing.end(), {"--output", Path("h.json"), "--report", Path("no/h.html")});
  ExpectRefusal(Hecal(missing), "--report");
  EXPECT_FALSE(std::filesystem::exists(Path("h.json")));
}

// --robot-sigma MM,DEG: the robot's noise is held at the given levels (only the ray noise is
// estimated), written to the result as given.
TEST_F(CalibrateGlobal, UsesAndWritesTheGivenRobotSigma) {
  testing::EpipolarSceneSpec spec;
  spec.motions = 4;
  spec.pairs = 20;
  spec.pixel_sigma = 0.5;
  spec.robot_rotation_sigma = 0.03 * M_PI / 180.0;
  spec.robot_translation_sigma = 0.25e-3;
  WriteScene(testing::MakeEpipolarScene(spec, 21));
  const std::vector<std::string> common = {"calibrate",
                                           "--method",
                                           "global",
                                           "--robot",
                                           Path("robot.csv"),
                                           "--setup",
                                           "eye-in-hand",
                                           "--reach",
                                           "1",
                                           "--max-cubes",
                                           "5000",
                                           "--correspondences",
                                           Path("pixels.csv"),
                                           "--intrinsics",
                                           Path("camera.yaml")};
  std::vector<std::string> given = common;
  given.insert(given.end(), {"--robot-sigma", "0.25,0.03", "--output", Path("given.json")});
  const auto run = Hecal(given);
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_NE(run.out.find("noise (robot given, ray estimated)"), std::string::npos) << run.out;
  const nlohmann::json doc = nlohmann::json::parse(Read("given.json"));
  EXPECT_EQ(doc["covariance"]["robot_sigma"], "given");
  EXPECT_NEAR(doc["covariance"]["robot_rotation_sigma_rad"].get<double>(), 0.03 * M_PI / 180.0,
              1e-15);
  EXPECT_NEAR(doc["covariance"]["robot_translation_sigma_m"].get<double>(), 0.25e-3, 1e-15);
  // Without the flag the levels are estimated.
  std::vector<std::string> estimated = common;
  estimated.insert(estimated.end(), {"--output", Path("estimated.json")});
  const auto plain = Hecal(estimated);
  ASSERT_EQ(plain.code, 0) << plain.err;
  EXPECT_NE(plain.out.find("noise (estimated)"), std::string::npos) << plain.out;
  EXPECT_EQ(nlohmann::json::parse(Read("estimated.json"))["covariance"]["robot_sigma"],
            "estimated");
  // Out of range: refused naming the flag.
  std::vector<std::string> bad = common;
  bad.insert(bad.end(), {"--robot-sigma", "0.25,-1", "--output", Path("bad.json")});
  const auto refused = Hecal(bad);
  EXPECT_EQ(refused.code, 2);
  EXPECT_EQ(refused.err.rfind("hecal: --robot-sigma: ", 0), 0u) << refused.err;
}

TEST_F(CalibrateGlobal, RefusesBadInputWithOneLineAndNoFile) {
  auto run = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = {"calibrate",       "--method", "global",        "--robot",
                                     Path("robot.csv"), "--output", Path("out.json")};
    args.insert(args.end(), extra.begin(), extra.end());
    return Hecal(args);
  };
  ExpectRefusal(run({"--setup", "eye-in-hand"}), "needs point matches");
  ExpectRefusal(run({"--setup", "auto", "--correspondences", Path("bearings.csv")}),
                "needs the setup");
  ExpectRefusal(run({"--setup", "eye-in-hand", "--correspondences", Path("pixels.csv")}),
                "gives pixels");
  Write("unknown.csv", "first,second,x1,y1,z1,x2,y2,z2\ns0,s99,0,0,1,0,0,1\n");
  ExpectRefusal(run({"--setup", "eye-in-hand", "--correspondences", Path("unknown.csv")}),
                "unknown.csv:2: station 's99' is not in");
  Write("bad.csv", "first,second,x1,y1,z1,x2,y2,z2\ns0,s1,0,0,1,0,0\n");
  ExpectRefusal(run({"--setup", "eye-in-hand", "--correspondences", Path("bad.csv")}),
                "bad.csv:2:");
  ExpectRefusal(
      run({"--setup", "eye-in-hand", "--correspondences", Path("bearings.csv"), "--epsilon", "0"}),
      "--epsilon");
  ExpectRefusal(run({"--setup", "eye-in-hand", "--correspondences", Path("bearings.csv"),
                     "--relative-gap", "1"}),
                "--relative-gap");
  // Target images: corners need the intrinsics and a target; one source of matches.
  const std::vector<std::string> images = {"--setup",  "eye-in-hand",
                                           "--images", Path("."),
                                           "--target", Write("target.yaml", "type: chessboard\n")};
  auto with = [&](std::vector<std::string> extra) {
    extra.insert(extra.begin(), images.begin(), images.end());
    return run(extra);
  };
  ExpectRefusal(
      with({"--intrinsics", Path("camera.yaml"), "--correspondences", Path("bearings.csv")}),
      "--images and --correspondences were both given");
  ExpectRefusal(with({}), "needs the camera's intrinsics");
  ExpectRefusal(with({"--intrinsics", Path("camera.yaml"), "--matches-per-motion", "3"}),
                "--matches-per-motion");
  ExpectRefusal(
      run({"--setup", "eye-in-hand", "--images", Path("."), "--intrinsics", Path("camera.yaml")}),
      "needs --target");
  ExpectRefusal(run({"--setup", "eye-in-hand", "--images", Path("."), "--target", "none",
                     "--intrinsics", Path("camera.yaml"), "--features", "surf"}),
                "unknown feature kind 'surf'");
  // Generic features (--target none) are for --method global only.
  ExpectRefusal(Hecal({"calibrate", "--method", "ml", "--robot", Path("robot.csv"), "--setup",
                       "eye-in-hand", "--images", Path("."), "--target", "none", "--intrinsics",
                       Path("camera.yaml"), "--output", Path("out.json")}),
                "works with --method global only");
  EXPECT_FALSE(std::filesystem::exists(Path("out.json")));
}

}  // namespace
}  // namespace hecal::cli
