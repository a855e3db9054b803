// The input of `hecal report` (docs/report.md): a calibration result file (docs/result-file.md)
// read strictly. Every field the page shows is checked for presence and type before anything is
// written; a bad or foreign file is an InputError naming the file and the field, e.g.
//   result.json: field results[0].X.matrix: expected a 4x4 matrix of numbers (fix: …)
// Accepted: one method's object, or {"results": [...]} of `--method all` (a method that refused
// the data, {"method", "error"}, is kept as such); the target-free result of `--method global`
// (report/global_result.h) has its own reader below. Anything else (a study CSV, another JSON)
// is refused naming the first field that is not there or not of its type.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace hecal::report {

// The results, always as {"results": [R, ...]} with "all_methods": true when the file was the
// `--method all` form; each R has been checked against docs/result-file.md. `source` names the
// file in errors.
// Refuses the target-free result (IsGlobalResult).
nlohmann::json ParseResultForReport(std::string_view text, const std::string& source);

// Whether a parsed JSON document is the target-free result (method `global` with a
// "certificate").
bool IsGlobalResult(const nlohmann::json& document);

// The target-free result file (docs/result-file.md#target-free---method-global), every field the
// global page shows checked; "motions" (per-motion residuals) is optional, files of older hecal
// versions lack it.
nlohmann::json ParseGlobalResultForReport(std::string_view text, const std::string& source);

}  // namespace hecal::report
