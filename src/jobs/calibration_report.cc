// The HTML report as a job: jobs/calibration_report.h, docs/report.md.
#include "hecal/jobs/calibration_report.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <vector>

#include "hecal/core/options_check.h"
#include "hecal/io/atomic_file.h"
#include "hecal/jobs/report_thumbnails.h"
#include "hecal/report/global_page.h"
#include "hecal/report/html_report.h"
#include "hecal/report/report_input.h"

namespace hecal::jobs {
namespace {

// The robot poses of the used stations of the page's first result that has stations, in the
// result's length unit. A row is that of the station named by its id column; without one, row k
// is station_order[k] (calibrate's stations in table order: the image names of --images) or,
// from a result file, the station named "k".
void AddRobotPoses(const CalibrationReportOptions& options,
                   const std::vector<std::string>& station_order, report::HtmlReportInput* input) {
  if (options.robot.empty()) return;
  const io::PoseTable table = io::ReadPoseTable(options.robot, options.robot_read);
  std::map<std::string, const io::PoseRow*> rows;
  for (size_t k = 0; k < table.rows.size(); ++k) {
    const std::string by_row = k < station_order.size() ? station_order[k] : std::to_string(k);
    rows[table.rows[k].id.value_or(by_row)] = &table.rows[k];
  }
  for (const nlohmann::json& result : input->results["results"]) {
    if (!result.contains("stations")) continue;
    const double scale = result["units"]["length"].get<std::string>() == "mm" ? 1000.0 : 1.0;
    for (const nlohmann::json& id : result["stations"]["used"]) {
      const auto it = rows.find(id.get<std::string>());
      if (it == rows.end()) {
        throw InputError(
            options.robot, 0,
            "the result's station '" + id.get<std::string>() + "' is not in this table",
            "give the robot pose table the result was calibrated from");
      }
      Eigen::Matrix4d T = it->second->pose.matrix();
      T.topRightCorner<3, 1>() *= scale;
      input->robot_poses.push_back(T);
      input->robot_lines.push_back(it->second->line);
    }
    return;
  }
}

// The thumbnails of the used images of the page's result from images, read from
// options.images.
void AddThumbnails(const CalibrationReportOptions& options, const std::string& source,
                   report::HtmlReportInput* input) {
  if (options.images.empty()) return;
  const nlohmann::json& results = input->results["results"];
  const auto it = std::find_if(results.begin(), results.end(),
                               [](const nlohmann::json& r) { return r.contains("images"); });
  if (it == results.end()) {
    throw InputError("--images", 0, "the result " + source + " is not from images",
                     "leave --images out (it gives the image folder of a result of `hecal "
                     "calibrate --images`)");
  }
  std::vector<ReportImage> images;
  const nlohmann::json& per_image = (*it)["images"]["per_image"];
  for (size_t k = 0; k < per_image.size(); ++k) {
    if (!per_image[k].contains("file")) {
      throw InputError(source, 0,
                       "field images.per_image[" + std::to_string(k) +
                           "].file is missing: the result does not name its image files (it "
                           "was written by an older hecal)",
                       "calibrate again with this hecal (calibrate --images DIR --output FILE), "
                       "or leave --images out");
    }
    images.push_back(
        {per_image[k]["id"].get<std::string>(), per_image[k]["file"].get<std::string>()});
  }
#if defined(HECAL_HAVE_VISION)
  input->thumbnails = ReadThumbnails(options.images, images, "--images");
#else
  throw InputError("--images", 0, "this hecal was built without the vision layer (OpenCV)",
                   "rebuild with -DHECAL_BUILD_VISION=ON, or leave --images out");
#endif
}

void Write(const std::string& text, const std::string& source, const std::string& title,
           const std::vector<std::string>& station_order, const CalibrationReportOptions& options) {
  report::HtmlReportInput input;
  input.results = report::ParseResultForReport(text, source);
  input.title = title;
  AddRobotPoses(options, station_order, &input);
  AddThumbnails(options, source, &input);
  report::WriteHtmlReport(options.output, input);
}

}  // namespace

bool CalibrationReportOptions::IsValid(std::string* why) const {
  if (output.empty())
    return Invalid(why, "CalibrationReportOptions.output", "no output file",
                   "name the page, e.g. report.html");
  return true;
}

void WriteCalibrationReport(const CalibrationReportOptions& options) {
  RequireValid(options);
  if (options.result.empty()) {
    throw InputError("CalibrationReportOptions.result", 0, "no result file",
                     "name the result file calibrate wrote");
  }
  const std::string text = io::ReadFile(options.result);
  const std::string title = std::filesystem::path(options.result).filename().string();
  if (report::IsGlobalResult(nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false))) {
    if (!options.robot.empty()) {
      throw InputError("--robot", 0, "the target-free result's page has no robot scene",
                       "leave --robot out for a `--method global` result (docs/report.md)");
    }
    if (!options.images.empty()) {
      throw InputError("--images", 0, "the result " + options.result + " is not from images",
                       "leave --images out for a `--method global` result (docs/report.md)");
    }
    return io::WriteFileAtomically(options.output,
                                   report::FormatGlobalReport(text, options.result, title));
  }
  Write(text, options.result, title, {}, options);
}

void WriteCalibrationReport(const report::ResultDocument& document, const std::string& title,
                            const CalibrationReportOptions& options) {
  RequireValid(options);
  Write(report::FormatResult(document, report::ResultFormat::kJson), title, title,
        document.station_ids, options);
}

}  // namespace hecal::jobs
