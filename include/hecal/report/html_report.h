// The interactive HTML report of a calibration result (`hecal report`, `calibrate --report`;
// docs/report.md): one self-contained page that opens offline from any folder. The figures are
// drawn in the browser by Plotly.js (web/package.json pins it) from one JSON blob of page data,
// by the page scripts web/page.js, web/images.js and web/calibration.js (web/detect.js draws the
// detect page, detection_page.h); the scripts and web/report.css are built
// into the library (src/report/CMakeLists: an assembler .incbin of the files that `npm ci`
// installed in web/), so the binary needs no file at run time and the page loads nothing from the
// network.
//
// The page data are the checked results (report_input.h) with every station's residual (and,
// from images, every detected point and its residual: web/images.js draws them), except
// that above kMaxPlottedStations stations the residual plots keep every flagged station and an
// even sample of the rest, and the 3D scene at most kMaxScenePoses gripper poses; the page says
// so when it happens. Its size is printed on the page (Plotly.js is ~4.9 MB of it), and that of
// the image thumbnails when there are any.
#pragma once

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "hecal/report/page_thumbnails.h"

namespace hecal::report {

constexpr size_t kMaxPlottedStations = 2000;
constexpr size_t kMaxScenePoses = 200;

struct HtmlReportInput {
  nlohmann::json results;  // ParseResultForReport's value
  std::string title;       // the result's name, e.g. the result file's name
  // The robot's poses T_base_gripper (4×4, translation in the result's length unit) of the used
  // stations, in order, for the 3D scene; empty: the scene shows the base, X and Z only.
  std::vector<Eigen::Matrix4d> robot_poses;
  // With robot_poses: each used station's 1-based line in the robot pose file (shown on hover).
  std::vector<int> robot_lines;
  // From images: thumbnails of the used images (page_thumbnails.h), by station id; empty when
  // the images are not at hand (the page says how to add them).
  std::vector<Thumbnail> thumbnails;
};

// The page shell of every kind of report: `data` is one JSON object with "kind" (the page script
// that draws it: "calibration" is web/calibration.js, "detect" web/detect.js
// (detection_page.h), "simulate" web/simulate.js (simulate_page.h), "contour_study"
// web/contour_study.js (contour_study_file.h), "global" web/global.js (global_page.h); each kind's
// script registers itself in web/page.js's hecalPage.pages and is listed in html_report.cc's
// kPageScripts) and "title"; the shell adds "hecal_version" and "page_bytes" (the page's own size)
// and embeds Plotly.js, web/page.js, every page script and web/report.css.
std::string FormatHtmlPage(nlohmann::json data);

// The calibration page.
std::string FormatHtmlReport(const HtmlReportInput& input);
// Written atomically (io/atomic_file.h): complete or absent.
void WriteHtmlReport(const std::string& path, const HtmlReportInput& input);

}  // namespace hecal::report
