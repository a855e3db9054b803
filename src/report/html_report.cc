// The page of the HTML report: html_report.h, docs/report.md.
#include "hecal/report/html_report.h"

#include <cstdio>
#include <string_view>

#include "hecal/io/atomic_file.h"
#include "hecal/report/json_matrix.h"
#include "hecal/version.h"

// The web assets, from the generated report_assets.S (src/report/CMakeLists.txt).
extern "C" {
extern const char hecal_report_plotly_js[];
extern const char hecal_report_plotly_js_end[];
extern const char hecal_report_page_js[];
extern const char hecal_report_page_js_end[];
extern const char hecal_report_images_js[];
extern const char hecal_report_images_js_end[];
extern const char hecal_report_calibration_js[];
extern const char hecal_report_calibration_js_end[];
extern const char hecal_report_detect_js[];
extern const char hecal_report_detect_js_end[];
extern const char hecal_report_simulate_js[];
extern const char hecal_report_simulate_js_end[];
extern const char hecal_report_contour_study_js[];
extern const char hecal_report_contour_study_js_end[];
extern const char hecal_report_global_js[];
extern const char hecal_report_global_js_end[];
extern const char hecal_report_page_css[];
extern const char hecal_report_page_css_end[];
}

namespace hecal::report {
namespace {

using nlohmann::json;

std::string_view Asset(const char* begin, const char* end) {
  return {begin, static_cast<size_t>(end - begin)};
}

// The scripts after web/page.js: the figures shared by pages (web/images.js), then the page
// kinds' scripts, each registering itself in hecalPage.pages.
struct Script {
  const char* begin;
  const char* end;
};
const Script kPageScripts[] = {
    {hecal_report_images_js, hecal_report_images_js_end},
    {hecal_report_calibration_js, hecal_report_calibration_js_end},
    {hecal_report_detect_js, hecal_report_detect_js_end},
    {hecal_report_simulate_js, hecal_report_simulate_js_end},
    {hecal_report_contour_study_js, hecal_report_contour_study_js_end},
    {hecal_report_global_js, hecal_report_global_js_end},
};

// At most `limit` of `stations`: every outlier and an even sample of the others, in order; each
// keeps its position in the file as "index".
json SampleStations(const json& stations, size_t limit, bool* sampled) {
  const size_t n = stations.size();
  const size_t stride = n <= limit ? 1 : (n + limit - 1) / limit;
  *sampled = *sampled || stride > 1;
  json out = json::array();
  for (size_t k = 0; k < n; ++k) {
    if (k % stride != 0 && !stations[k].value("outlier", false)) continue;
    json station = stations[k];
    station["index"] = k;
    out.push_back(std::move(station));
  }
  return out;
}

json PageData(const HtmlReportInput& input) {
  json data = {{"kind", "calibration"},
               {"title", input.title},
               {"all_methods", input.results.at("all_methods")},
               {"results", json::array()},
               {"notes", json::array()}};
  bool sampled = false;
  for (json result : input.results.at("results")) {
    if (result.contains("residuals")) {
      json& residuals = result["residuals"];
      residuals["stations_total"] = residuals["per_station"].size();
      residuals["per_station"] =
          SampleStations(residuals["per_station"], kMaxPlottedStations, &sampled);
    }
    data["results"].push_back(std::move(result));
  }
  if (sampled) {
    data["notes"].push_back("More than " + std::to_string(kMaxPlottedStations) +
                            " stations: the residual plots show every flagged station and an "
                            "even sample of the others; the numbers use every station.");
  }
  for (const json& result : data["results"]) {
    if (!result.contains("images")) continue;
    data["thumbnails"] = ThumbnailsJson(input.thumbnails, result["images"]["per_image"].size());
    break;
  }
  const size_t n = input.robot_poses.size();
  const size_t stride = n <= kMaxScenePoses ? 1 : (n + kMaxScenePoses - 1) / kMaxScenePoses;
  json poses = json::array();
  for (size_t k = 0; k < n; k += stride) poses.push_back(JsonRows(input.robot_poses[k]));
  data["robot_poses"] = poses;
  data["robot_pose_stride"] = stride;
  data["robot_lines"] = input.robot_lines;
  if (stride > 1) {
    data["notes"].push_back("The 3D scene shows every " + std::to_string(stride) + "th of the " +
                            std::to_string(n) + " robot poses.");
  }
  return data;
}

// JSON inside <script>: "</" would end the element; "<\/" is the same JSON string.
std::string ScriptSafe(std::string text) {
  for (size_t at = text.find("</"); at != std::string::npos; at = text.find("</", at + 3))
    text.replace(at, 2, "<\\/");
  return text;
}

std::string Page(const std::string& data) {
  std::string page;
  page.reserve(data.size() + 5'200'000);
  page += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  page += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  page += "<meta name=\"generator\" content=\"hecal ";
  page += hecal::kVersion;
  page += "\">\n<title>hecal report</title>\n<style>\n";
  page += Asset(hecal_report_page_css, hecal_report_page_css_end);
  page += "</style>\n</head>\n<body>\n<main id=\"report\"></main>\n";
  page += "<script type=\"application/json\" id=\"hecal-data\">";
  page += data;
  page += "</script>\n<script>\n";
  page += Asset(hecal_report_plotly_js, hecal_report_plotly_js_end);
  page += "\n</script>\n<script>\n";
  page += Asset(hecal_report_page_js, hecal_report_page_js_end);
  for (const Script& script : kPageScripts) {
    page += "\n</script>\n<script>\n";
    page += Asset(script.begin, script.end);
  }
  page += "\n</script>\n<script>hecalPage.render();</script>\n</body>\n</html>\n";
  return page;
}

}  // namespace

std::string FormatHtmlReport(const HtmlReportInput& input) {
  return FormatHtmlPage(PageData(input));
}

void WriteHtmlReport(const std::string& path, const HtmlReportInput& input) {
  io::WriteFileAtomically(path, FormatHtmlReport(input));
}

std::string FormatHtmlPage(json data) {
  data["hecal_version"] = hecal::kVersion;
  // The page states its own size: the number is part of the page, so settle it by iterating.
  size_t bytes = 0;
  std::string page;
  for (int round = 0; round < 3; ++round) {
    data["page_bytes"] = bytes;
    page = Page(ScriptSafe(data.dump()));
    if (page.size() == bytes) break;
    bytes = page.size();
  }
  return page;
}

}  // namespace hecal::report
