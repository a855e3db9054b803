// The input of `hecal report` (docs/report.md): a calibration result file (docs/result-file.md)
// read strictly. Every field the page shows is checked for presence and type before anything is
// written; a bad or foreign file is an InputError naming the file and the field, e.g.
//   result.json: field results[0].X.matrix: expected a 4x4 matrix of numbers (fix: …)
// Accepted: one method's object, or {"results": [...]} of `--method all` (a method that refused
// the data, {"method", "error"}, is kept as such). Other hecal files (the target-free result of
// `--method global`, a study CSV) are refused with the command that reports them.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace hecal::report {

// The results, always as {"results": [R, ...]} with "all_methods": true when the file was the
// `--method all` form; each R has been checked against docs/result-file.md. `source` names the
// file in errors.
nlohmann::json ParseResultForReport(std::string_view text, const std::string& source);

}  // namespace hecal::report
