#include "hecal/report/report_input.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "hecal/core/error.h"
#include "hecal/geometry/se3.h"
#include "hecal/report/result_file.h"

namespace hecal::report {
namespace {

using nlohmann::json;

ResultDocument MakeDocument(bool all) {
  ResultDocument document;
  document.setup = handeye::Setup::kEyeInHand;
  document.station_ids = {"a", "b", "c", "d"};
  document.rejected = {3};
  estimation::CalibrationResult result;
  result.X = se3::Exp((Vector6d() << 0.1, 0.2, -0.3, 0.01, -0.02, 0.05).finished());
  result.Z = se3::Exp((Vector6d() << -0.5, 0.0, 0.25, 0.4, 0.2, 0.3).finished());
  estimation::CalibrationCovariance covariance;
  covariance.covariance = Eigen::Matrix<double, 12, 12>::Identity() * 1e-6;
  result.covariance = covariance;
  result.residuals = {
      {0.01, 0.002, 0.9, false}, {0.02, 0.004, 4.0, true}, {0.01, 0.001, 0.5, false}};
  result.rejected = {3};
  result.rejected_residuals = {{0.5, 0.1, 40.0, true}};
  result.warnings = {"noise not given"};
  document.results = {result};
  if (all) {
    document.all_methods = true;
    document.failures = {{estimation::Method::kDaniilidis, "screw check failed"}};
  }
  return document;
}

std::string Text(const ResultDocument& document) {
  return FormatResult(document, ResultFormat::kJson);
}

// The message of the InputError that `text` raises ("" when it raises none).
std::string ErrorOf(const std::string& text) {
  try {
    ParseResultForReport(text, "r.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ReportInput, ReadsWhatCalibrateWrites) {
  const json one = ParseResultForReport(Text(MakeDocument(false)), "r.json");
  EXPECT_FALSE(one["all_methods"].get<bool>());
  ASSERT_EQ(one["results"].size(), 1u);
  EXPECT_EQ(one["results"][0]["residuals"]["per_station"].size(), 3u);
  const json all = ParseResultForReport(Text(MakeDocument(true)), "r.json");
  EXPECT_TRUE(all["all_methods"].get<bool>());
  ASSERT_EQ(all["results"].size(), 2u);  // the method and the one that refused
  EXPECT_EQ(all["results"][1]["error"], "screw check failed");
}

TEST(ReportInput, NamesTheBadField) {
  json j = json::parse(Text(MakeDocument(true)));
  j["results"][0]["X"]["matrix"][1] = json::array({1, 2});
  EXPECT_EQ(ErrorOf(j.dump()),
            "r.json: field results[0].X.matrix: expected a 4x4 matrix of numbers (fix: give a "
            "result file written by `hecal calibrate --output FILE.json` (docs/result-file.md))");
  j = json::parse(Text(MakeDocument(false)));
  j["residuals"]["per_station"][1].erase("whitened");
  EXPECT_NE(ErrorOf(j.dump()).find("field residuals.per_station[1].whitened is missing"),
            std::string::npos);
  j = json::parse(Text(MakeDocument(false)));
  j["setup"] = "eye-on-hand";
  EXPECT_NE(ErrorOf(j.dump()).find("field setup: expected eye-in-hand or eye-to-hand"),
            std::string::npos);
  j = json::parse(Text(MakeDocument(false)));
  j["covariance"]["sigma"]["Z"]["rotation_deg"] = "small";
  EXPECT_NE(ErrorOf(j.dump()).find("field covariance.sigma.Z.rotation_deg: expected 3 finite"),
            std::string::npos);
  j = json::parse(Text(MakeDocument(false)));
  j["warnings"][0] = 7;
  EXPECT_NE(ErrorOf(j.dump()).find("field warnings[0]: expected a string"), std::string::npos);
}

// MakeDocument with the images section of `calibrate --images`, per-point fields included.
ResultDocument WithImages(ResultDocument document) {
  ImageReport images;
  images.intrinsics_source = "camera.yaml";
  images.camera.fx = images.camera.fy = 500.0;
  images.camera.width = 640;
  images.camera.height = 480;
  images.pixel_sigma = 0.2;
  images.rms_px = 0.25;
  images.image_rms_px = {0.2, 0.3, 0.25};
  images.image_outlier = {false, false, false};
  images.skipped_reasons = {"target not found"};
  images.image_files = {"a.png", "b.png", "c.png"};
  for (int k = 0; k < 3; ++k) {
    images.image_points_px.push_back({{100.123456, 200.0}, {300.5, 400.25}});
    images.image_residuals_px.push_back({{0.01234567, -0.2}, {0.1, 0.0}});
  }
  images.pose_level = document.results[0];
  document.images = images;
  return document;
}

TEST(ReportInput, ReadsThePerPointFields) {
  const json r = ParseResultForReport(Text(WithImages(MakeDocument(false))), "r.json");
  const json& image = r["results"][0]["images"]["per_image"][1];
  EXPECT_EQ(image["file"], "b.png");
  // Written rounded: points to 0.01 px, residuals to 0.001 px.
  EXPECT_EQ(image["points_px"][0], json::array({100.12, 200.0}));
  EXPECT_EQ(image["residuals_px"][0], json::array({0.012, -0.2}));
  // Older files have none of them.
  json j = json::parse(Text(WithImages(MakeDocument(false))));
  for (json& p : j["images"]["per_image"]) {
    p.erase("file");
    p.erase("points_px");
    p.erase("residuals_px");
  }
  EXPECT_EQ(ErrorOf(j.dump()), "");
}

TEST(ReportInput, NamesABadPerPointField) {
  json j = json::parse(Text(WithImages(MakeDocument(false))));
  j["images"]["per_image"][2]["points_px"][1] = json::array({1.0});
  EXPECT_NE(ErrorOf(j.dump()).find("field images.per_image[2].points_px[1]: expected [u, v]"),
            std::string::npos);
  j = json::parse(Text(WithImages(MakeDocument(false))));
  j["images"]["per_image"][0]["residuals_px"].erase(0);
  EXPECT_NE(ErrorOf(j.dump()).find(
                "field images.per_image[0].residuals_px: expected one [du, dv] per point"),
            std::string::npos);
  j = json::parse(Text(WithImages(MakeDocument(false))));
  j["images"]["per_image"][0].erase("residuals_px");
  EXPECT_NE(ErrorOf(j.dump()).find("field images.per_image[0].residuals_px is missing"),
            std::string::npos);
  j = json::parse(Text(WithImages(MakeDocument(false))));
  j["images"]["per_image"][0]["file"] = 3;
  EXPECT_NE(ErrorOf(j.dump()).find("field images.per_image[0].file: expected a string"),
            std::string::npos);
}

TEST(ReportInput, RefusesForeignFiles) {
  EXPECT_NE(ErrorOf("x,y,z\n1,2,3\n").find("not JSON"), std::string::npos);
  EXPECT_NE(ErrorOf("[1, 2]").find("field (top level): expected a JSON object"), std::string::npos);
  EXPECT_NE(ErrorOf(R"({"name": "a package.json"})").find("field hecal_version is missing"),
            std::string::npos);
  EXPECT_NE(ErrorOf(R"({"results": []})").find("field results: expected at least one result"),
            std::string::npos);
  EXPECT_NE(ErrorOf(R"({"method": "global", "certificate": {}})").find("target-free"),
            std::string::npos);
}

}  // namespace
}  // namespace hecal::report
