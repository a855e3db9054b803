#include "hecal/report/html_report.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "hecal/report/detection_page.h"

namespace hecal::report {
namespace {

using nlohmann::json;

// The page data blob of a page.
json PageData(const std::string& page) {
  const std::string open = "<script type=\"application/json\" id=\"hecal-data\">";
  const size_t begin = page.find(open) + open.size();
  return json::parse(page.substr(begin, page.find("</script>", begin) - begin));
}

HtmlReportInput Input(size_t stations) {
  json per_station = json::array();
  for (size_t k = 0; k < stations; ++k)
    per_station.push_back({{"id", std::to_string(k)}, {"whitened", 1.0}, {"outlier", k == 7}});
  HtmlReportInput input;
  input.title = "r.json </script> title";
  input.results = {
      {"all_methods", false},
      {"results",
       json::array({{{"method", "ml"}, {"residuals", {{"per_station", per_station}}}}})}};
  return input;
}

TEST(HtmlReport, IsOnePageWithEverythingInside) {
  const std::string page = FormatHtmlReport(Input(5));
  EXPECT_EQ(page.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(page.find("Plotly"), std::string::npos);      // the embedded library
  EXPECT_NE(page.find("hecal-data"), std::string::npos);  // the page script reads this
  // Nothing from elsewhere: no <script src>, no stylesheet link (the browser test checks
  // that the page makes no request).
  EXPECT_EQ(page.find("<script src"), std::string::npos);
  EXPECT_EQ(page.find("<link"), std::string::npos);
  const json data = PageData(page);
  EXPECT_EQ(data["title"], "r.json </script> title");  // escaped as <\/ in the page
  EXPECT_EQ(data["kind"], "calibration");
  // The shell, then the calibration page's script, then the call that draws the page.
  const size_t shell = page.find("const hecalPage");
  const size_t calibration = page.find("hecalPage.pages.calibration =");
  ASSERT_NE(shell, std::string::npos);
  ASSERT_NE(calibration, std::string::npos);
  EXPECT_LT(shell, calibration);
  EXPECT_LT(calibration, page.find("hecalPage.render();"));
  EXPECT_EQ(data["page_bytes"].get<size_t>(), page.size());
  EXPECT_EQ(data["results"][0]["residuals"]["per_station"].size(), 5u);
  EXPECT_TRUE(data["notes"].empty());
}

TEST(HtmlReport, ShellTakesAnyKindOfPage) {
  const std::string page = FormatHtmlPage({{"kind", "study"}, {"title", "s"}, {"x", 1}});
  const json data = PageData(page);
  EXPECT_EQ(data["kind"], "study");
  EXPECT_EQ(data["x"], 1);
  EXPECT_EQ(data["page_bytes"].get<size_t>(), page.size());
  EXPECT_FALSE(data["hecal_version"].get<std::string>().empty());
}

TEST(HtmlReport, ImagesGetTheirThumbnails) {
  HtmlReportInput input = Input(2);
  input.results["results"][0]["images"] = {
      {"per_image", json::array({{{"id", "0"}}, {{"id", "1"}}})}};
  json data = PageData(FormatHtmlReport(input));
  EXPECT_EQ(data["thumbnails"]["count"], 0);  // not at hand: the page says how to add them
  EXPECT_EQ(data["thumbnails"]["images"], 2);
  input.thumbnails = {{"1", "jpeg"}};
  data = PageData(FormatHtmlReport(input));
  EXPECT_EQ(data["thumbnails"]["by_id"]["1"], "data:image/jpeg;base64,anBlZw==");
  // The shared image figures come before the page scripts that use them.
  const std::string page = FormatHtmlReport(input);
  EXPECT_LT(page.find("hecalPage.imageFigures ="), page.find("hecalPage.pages.calibration ="));
  EXPECT_LT(page.find("hecalPage.imageFigures ="), page.find("hecalPage.pages.detect ="));
}

TEST(HtmlReport, DetectPage) {
  DetectionPageInput input;
  input.title = "images";
  input.camera.width = 640;
  input.camera.height = 480;
  DetectionPageImage used;
  used.id = "a";
  used.file = "a.png";
  used.points_px = {{10.004, 20.0}};
  used.residuals_px = {{0.0123, -0.0004}};
  used.rms_px = 0.0123;
  DetectionPageImage skipped;
  skipped.id = "b";
  skipped.skipped = "target not found";
  input.images = {used, skipped};
  input.thumbnails = {{"a", "x"}};
  const json data = PageData(FormatDetectionPage(input));
  EXPECT_EQ(data["kind"], "detect");
  ASSERT_EQ(data["per_image"].size(), 1u);
  EXPECT_EQ(data["per_image"][0]["points_px"][0], json::array({10.0, 20.0}));
  EXPECT_EQ(data["per_image"][0]["residuals_px"][0], json::array({0.012, -0.0}));
  EXPECT_EQ(data["per_image"][0]["T_camera_target"].size(), 4u);
  EXPECT_EQ(data["skipped"][0]["reason"], "target not found");
  EXPECT_EQ(data["intrinsics"]["width"], 640);
  EXPECT_EQ(data["thumbnails"]["count"], 1);
}

TEST(HtmlReport, SamplesManyStationsAndSaysSo) {
  HtmlReportInput input = Input(10'000);
  for (int k = 0; k < 10'000; ++k) input.robot_poses.push_back(Eigen::Matrix4d::Identity());
  const json data = PageData(FormatHtmlReport(input));
  const json& plotted = data["results"][0]["residuals"]["per_station"];
  EXPECT_LE(plotted.size(), kMaxPlottedStations + 1);
  EXPECT_EQ(data["results"][0]["residuals"]["stations_total"], 10'000);
  bool flagged_kept = false;
  for (const json& s : plotted) flagged_kept = flagged_kept || s["index"] == 7;
  EXPECT_TRUE(flagged_kept);
  EXPECT_LE(data["robot_poses"].size(), kMaxScenePoses);
  EXPECT_EQ(data["notes"].size(), 2u);
}

}  // namespace
}  // namespace hecal::report
