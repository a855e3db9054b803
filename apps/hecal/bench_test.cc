// `hecal bench` through RunHecal: the JSON contract (docs/bench.md), the table, bad flags.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli_test_util.h"

namespace hecal::cli {
namespace {

using cli_test::Hecal;
using cli_test::Outcome;

TEST(BenchCommand, JsonHasOneObjectPerImplMethodAndStations) {
  const Outcome run = Hecal({"bench", "--stations", "5,8", "--json", "--method",
                             "park-martin,chou-kamel", "--datasets", "2", "--min-time", "0"});
  ASSERT_EQ(run.code, 0) << run.err;
  const nlohmann::json array = nlohmann::json::parse(run.out);
  ASSERT_TRUE(array.is_array());
  std::set<std::string> keys;
  for (const nlohmann::json& row : array) {
    for (const char* field : {"impl", "method", "stations", "us_per_solve", "rotation_error_deg",
                              "translation_error"}) {
      EXPECT_TRUE(row.contains(field)) << field;
    }
    EXPECT_GT(row["us_per_solve"].get<double>(), 0.0);
    keys.insert(row["impl"].get<std::string>() + "/" + row["method"].get<std::string>() + "/" +
                std::to_string(row["stations"].get<int>()));
    if (row["impl"] == "hecal") {
      // 0.1 mm / 0.1° noise: errors of a fraction of a degree and a few mm at most.
      EXPECT_LT(row["rotation_error_deg"].get<double>(), 1.0);
      EXPECT_LT(row["translation_error"].get<double>(), 0.01);
      EXPECT_EQ(row["failures"].get<int>(), 0);
    }
  }
  for (const char* key :
       {"hecal/park-martin/5", "hecal/park-martin/8", "hecal/chou-kamel/5", "hecal/chou-kamel/8"}) {
    EXPECT_TRUE(keys.count(key)) << key;
  }
#ifdef HECAL_HAVE_OPENCV_PEERS
  EXPECT_TRUE(keys.count("opencv/park-martin/8"));
  EXPECT_FALSE(keys.count("opencv/chou-kamel/8"));  // OpenCV has no Chou–Kamel
  EXPECT_EQ(array.size(), 6u);
#else
  EXPECT_EQ(array.size(), 4u);
#endif
}

// ml is timed twice: from the closed-form starts and from a good start (the truth), both right.
TEST(BenchCommand, MlHasAGoodStartRow) {
  const Outcome run = Hecal({"bench", "--stations", "8", "--json", "--method", "ml,andreff",
                             "--datasets", "2", "--min-time", "0"});
  ASSERT_EQ(run.code, 0) << run.err;
  std::set<std::string> keys;
  for (const nlohmann::json& row : nlohmann::json::parse(run.out)) {
    if (row["impl"] != "hecal") continue;
    keys.insert(row["method"].get<std::string>() + "/" +
                (row["start"].is_null() ? "null" : row["start"].get<std::string>()));
    EXPECT_LT(row["rotation_error_deg"].get<double>(), 1.0);
    EXPECT_EQ(row["failures"].get<int>(), 0);
  }
  EXPECT_EQ(keys, (std::set<std::string>{"ml/closed-form", "ml/good", "andreff/null"}));
  const Outcome table =
      Hecal({"bench", "--stations", "8", "--method", "ml", "--datasets", "1", "--min-time", "0"});
  ASSERT_EQ(table.code, 0) << table.err;
  EXPECT_NE(table.out.find("ml from a good start, n = 8: "), std::string::npos) << table.out;
  EXPECT_NE(table.out.find("faster than from the closed-form starts"), std::string::npos);
}

TEST(BenchCommand, TablePrintsTheSpeedUp) {
  const Outcome run = Hecal(
      {"bench", "--stations", "6", "--method", "andreff", "--datasets", "1", "--min-time", "0"});
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_NE(run.out.find("andreff"), std::string::npos);
  EXPECT_NE(run.out.find("speed-up"), std::string::npos);
}

TEST(BenchCommand, BadFlagsExitTwo) {
  for (const std::vector<std::string>& args :
       std::vector<std::vector<std::string>>{{"bench", "--stations", "2"},
                                             {"bench", "--method", "fast"},
                                             {"bench", "--setup", "both"},
                                             {"bench", "--datasets", "0"},
                                             {"bench", "--sigma", "-0.1"},
                                             {"bench", "--min-time", "-1"}}) {
    const Outcome run = Hecal(args);
    EXPECT_EQ(run.code, 2) << args[1];
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  }
}

}  // namespace
}  // namespace hecal::cli
