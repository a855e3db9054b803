// The target-free page (global_page.h) and the strict reading of its result file
// (report_input.h: ParseGlobalResultForReport): the answer in degrees and millimetres, the σ per
// axis, the per-motion residuals carried through, an older file without them, and a bad field
// named with nothing else read.
#include "hecal/report/global_page.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hecal/core/error.h"
#include "hecal/geometry/so3.h"
#include "hecal/report/global_result.h"
#include "hecal/report/report_input.h"

namespace hecal::report {
namespace {

using nlohmann::json;

GlobalCalibrationResult MakeResult() {
  GlobalCalibrationResult r;
  r.options.setup = handeye::Setup::kEyeInHand;
  Pose X = Pose::Identity();
  X.linear() = so3::Exp(Eigen::Vector3d(0.0, 0.0, std::numbers::pi / 2));  // 90° about z
  X.translation() = Eigen::Vector3d(0.01, -0.02, 0.1);
  r.robot_noise.polish.X = X;
  Matrix6d C = Matrix6d::Zero();
  C.diagonal() << 1e-6, 4e-6, 9e-6, 1e-6, 4e-6, 9e-6;  // 1σ: 1, 2, 3 mrad and mm
  r.robot_noise.polish.covariance = C;
  r.independent_covariance = C / 4.0;
  r.l_infinity_X = X;
  r.l_infinity_X.translation().x() += 0.003;
  r.covariance_check.check.reason = "too few stations";
  r.noise.ray_sigma = 1e-3;
  r.noise.robot_translation_sigma = 0.25e-3;
  r.inliers = 30;
  r.removed = {{"s1", "s2", 7, "epipolar ransac"}};
  r.motions = {{"s1", "s2", 14, 1, 2e-4, 5e-4}, {"s2", "s3", 16, 0, 1e-4, 3e-4}};
  return r;
}

TEST(GlobalPage, AnswerInDegreesAndMillimetresWithTheResidualsPerMotion) {
  const std::string text = GlobalResultJson(MakeResult());
  const json data = GlobalPageData(ParseGlobalResultForReport(text, "g.json"), "g.json");
  EXPECT_EQ(data["kind"], "global");
  EXPECT_EQ(data["title"], "g.json");
  const json& a = data["answer"];
  EXPECT_NEAR(a["angle_deg"].get<double>(), 90.0, 1e-9);
  EXPECT_NEAR(a["axis"][2].get<double>(), 1.0, 1e-12);
  EXPECT_NEAR(a["matrix_mm"][2][3].get<double>(), 100.0, 1e-9);
  EXPECT_NEAR(a["quaternion_wxyz"][0].get<double>(), std::sqrt(0.5), 1e-12);
  const double deg = 180.0 / std::numbers::pi;
  EXPECT_NEAR(a["sigma"]["rotation_deg"][1].get<double>(), 2e-3 * deg, 1e-9);
  EXPECT_NEAR(a["sigma"]["translation_mm"][2].get<double>(), 3.0, 1e-9);
  EXPECT_NEAR(a["sigma_independent_pairs"]["translation_mm"][2].get<double>(), 1.5, 1e-9);
  EXPECT_NEAR(a["l_infinity_from_X"]["distance_mm"].get<double>(), 3.0, 1e-9);
  EXPECT_NEAR(a["l_infinity_from_X"]["angle_deg"].get<double>(), 0.0, 1e-9);
  EXPECT_NEAR(data["noise"]["robot_translation_sigma_mm"].get<double>(), 0.25, 1e-12);
  const json& motions = data["result"]["motions"];
  ASSERT_EQ(motions.size(), 2u);
  EXPECT_EQ(motions[0]["first"], "s1");
  EXPECT_EQ(motions[0]["removed"], 1);
  EXPECT_EQ(motions[1]["rms_rad"], 1e-4);
  EXPECT_NE(FormatGlobalReport(text, "g.json", "g").find("\"kind\":\"global\""), std::string::npos);
}

TEST(GlobalPage, FilesWithoutPerMotionResidualsAreRead) {
  json file = json::parse(GlobalResultJson(MakeResult()));
  file.erase("motions");
  EXPECT_FALSE(ParseGlobalResultForReport(file.dump(), "old.json").contains("motions"));
}

TEST(GlobalPage, BadFieldIsNamedAndACalibrationResultIsNotTakenForIt) {
  json file = json::parse(GlobalResultJson(MakeResult()));
  file["covariance"]["X"][2] = {1, 2};
  try {
    ParseGlobalResultForReport(file.dump(), "g.json");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("g.json"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("field covariance.X: expected a 6x6 matrix"),
              std::string::npos)
        << e.what();
  }
  file = json::parse(GlobalResultJson(MakeResult()));
  file["motions"][1].erase("rms_rad");
  EXPECT_THROW(ParseGlobalResultForReport(file.dump(), "g.json"), InputError);
  EXPECT_THROW(ParseGlobalResultForReport("not json", "g.json"), InputError);
  EXPECT_THROW(ParseGlobalResultForReport(R"({"method": "ml"})", "g.json"), InputError);
  EXPECT_TRUE(IsGlobalResult(file));
  EXPECT_FALSE(IsGlobalResult(json::parse(R"({"method": "ml"})")));
}

}  // namespace
}  // namespace hecal::report
