// The page data of the target-free result (`hecal report GLOBAL.json`, `hecal calibrate --method
// global --report`; docs/report.md "The global page", docs/global.md): the result file
// (report_input.h: ParseGlobalResultForReport, docs/result-file.md) as the JSON blob that
// web/global.js draws (kind "global"; page shell: html_report.h's FormatHtmlPage), with what the
// page shows worked out here:
//  - "result": the checked file as it is (metres, radians);
//  - "answer": X as a 4×4 matrix in millimetres, its rotation as angle (degrees) and unit axis
//    and as a quaternion (w, x, y, z), the 1σ per axis of the right perturbation (degrees, mm)
//    from covariance.X and from covariance.independent_pairs_X, and how far the certified L∞ X
//    lies from X (angle in degrees, distance in mm);
//  - "noise": the ray σ in radians, the robot's σ in degrees and mm, given or estimated.
// The file has no Z: the target-free method has no target.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace hecal::report {

// `result`: ParseGlobalResultForReport's value.
nlohmann::json GlobalPageData(const nlohmann::json& result, const std::string& title);

// The page of a result file's text (GlobalResultJson's, or a file's; `source` names it in
// errors): ParseGlobalResultForReport, GlobalPageData, FormatHtmlPage.
std::string FormatGlobalReport(std::string_view result_json, const std::string& source,
                               const std::string& title);

}  // namespace hecal::report
