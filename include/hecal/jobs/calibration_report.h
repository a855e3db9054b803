// The HTML report of a calibration as a job (`hecal report`, `hecal calibrate --report`;
// docs/report.md): the result file (or the document calibrate just solved) read strictly
// (report/report_input.h), the robot's poses for the 3D scene when the robot pose table is given,
// and the page (report/html_report.h) written atomically.
//
// The 3D scene needs T_base_gripper per station, which the result file does not hold (it names
// stations by id only, docs/result-file.md): the job reads them from the robot table the result
// was calibrated from, matching the result's used station ids to the table's id column (or to
// the 0-based row index when the table has none; calibrate --report knows its stations' order, so
// image names match the table's rows in order). Without the table the scene shows the base and
// the fixed frame (X eye-to-hand, Z eye-in-hand) only.
//
// With `images` (a result from images), each used image's thumbnail: the result names its file
// (images.per_image[].file, written by this version on); the page shows the thumbnail under the
// image's detected points when clicked.
//
// A target-free result file (`--method global`, report::IsGlobalResult) gets the global page
// (report/global_page.h) instead; it takes no robot table and no images.
//
// Errors (InputError): the result file (not JSON, a missing or mistyped field, named as
// "field results[0].X.matrix"), the robot table (read errors, a station id it lacks), `images`
// given for a result that is not from images or names no files, an image missing from the folder
// or unreadable (named), `images` in a hecal built without the vision layer; nothing is written
// then.
#pragma once

#include <string>

#include "hecal/io/pose_table.h"
#include "hecal/report/result_file.h"

namespace hecal::jobs {

struct CalibrationReportOptions {
  std::string result;  // the result file (JSON, docs/result-file.md)
  std::string output;  // the page (.html)
  std::string robot;   // optional: the robot pose table (T_base_gripper) of the calibration
  io::PoseReadOptions robot_read;  // as calibrate read it (units, --degrees, --euler, inverse)
  // optional: the image folder of a result from images, for the thumbnails
  // (jobs/report_thumbnails.h): each used image's `file` (images.per_image) read from it.
  std::string images;

  // result and output given.
  bool IsValid(std::string* why) const;
};

// `hecal report`: reads options.result (a calibration or a target-free result), writes
// options.output.
void WriteCalibrationReport(const CalibrationReportOptions& options);

// `hecal calibrate --report`: the same page from the document in memory (options.result unused;
// the page's title names `title`).
void WriteCalibrationReport(const report::ResultDocument& document, const std::string& title,
                            const CalibrationReportOptions& options);

}  // namespace hecal::jobs
