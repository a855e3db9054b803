// The JSON of `hecal bench --json`: see bench_file.h.
#include "hecal/report/bench_file.h"

#include <nlohmann/json.hpp>

#include "hecal/geometry/angle_units.h"

namespace hecal::report {
namespace {

nlohmann::json StartJson(study::BenchStart start) {
  switch (start) {
    case study::BenchStart::kClosedForm:
      return "closed-form";
    case study::BenchStart::kGood:
      return "good";
    case study::BenchStart::kNotApplicable:
      break;
  }
  return nullptr;
}

nlohmann::json Optional(const std::optional<double>& value, double scale) {
  return value ? nlohmann::json(*value * scale) : nlohmann::json(nullptr);
}

}  // namespace

std::string BenchJson(const study::BenchResult& result) {
  nlohmann::json array = nlohmann::json::array();
  for (const study::BenchRow& row : result.rows) {
    nlohmann::json object;
    object["impl"] = row.impl;
    object["method"] = std::string(estimation::Info(row.method).name);
    object["start"] = StartJson(row.start);
    object["stations"] = row.stations;
    object["us_per_solve"] = row.us_per_solve;
    object["rotation_error_deg"] = Optional(row.accuracy.rotation_error, kDegreesPerRadian);
    object["translation_error"] = Optional(row.accuracy.translation_error, 1.0);
    object["translation_unit"] = "m";
    object["failures"] = row.accuracy.failures;
    object["datasets"] = row.datasets;
    object["seed"] = result.options.seed;
    array.push_back(std::move(object));
  }
  return array.dump(2) + "\n";
}

}  // namespace hecal::report
