#include "hecal/report/bench_file.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <numbers>

namespace hecal::report {
namespace {

// The fields of docs/bench.md, parsed back: units (degrees, metres), null errors, start values.
TEST(BenchJson, OneObjectPerRowWithTheDocumentedFields) {
  study::BenchResult result;
  result.options.seed = 42;
  study::BenchRow closed;
  closed.impl = "hecal";
  closed.method = estimation::Method::kParkMartin;
  closed.stations = 10;
  closed.us_per_solve = 12.5;
  closed.accuracy.rotation_error = std::numbers::pi / 180.0;  // 1 degree
  closed.accuracy.translation_error = 0.002;
  closed.accuracy.failures = 1;
  closed.datasets = 8;
  study::BenchRow good = closed;
  good.method = estimation::Method::kMl;
  good.start = study::BenchStart::kGood;
  good.accuracy.rotation_error.reset();
  good.accuracy.translation_error.reset();
  study::BenchRow multi = good;
  multi.start = study::BenchStart::kClosedForm;
  result.rows = {closed, good, multi};

  const std::string text = BenchJson(result);
  ASSERT_EQ(text.back(), '\n');
  const nlohmann::json rows = nlohmann::json::parse(text);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0]["impl"], "hecal");
  EXPECT_EQ(rows[0]["method"], "park-martin");
  EXPECT_TRUE(rows[0]["start"].is_null());
  EXPECT_EQ(rows[0]["stations"], 10);
  EXPECT_EQ(rows[0]["us_per_solve"], 12.5);
  EXPECT_NEAR(rows[0]["rotation_error_deg"].get<double>(), 1.0, 1e-12);
  EXPECT_EQ(rows[0]["translation_error"], 0.002);
  EXPECT_EQ(rows[0]["translation_unit"], "m");
  EXPECT_EQ(rows[0]["failures"], 1);
  EXPECT_EQ(rows[0]["datasets"], 8);
  EXPECT_EQ(rows[0]["seed"], 42);
  EXPECT_EQ(rows[1]["start"], "good");
  EXPECT_TRUE(rows[1]["rotation_error_deg"].is_null());
  EXPECT_TRUE(rows[1]["translation_error"].is_null());
  EXPECT_EQ(rows[2]["start"], "closed-form");
  EXPECT_EQ(rows[0].size(), 11u);
}

}  // namespace
}  // namespace hecal::report
