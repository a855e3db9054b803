// The page data of `hecal simulate --report` (simulate_page.h): its shape, the units, NaN as
// null, and the even sample of the trials above kMaxPlottedTrials.
#include "hecal/report/simulate_page.h"

#include <gtest/gtest.h>

#include <numbers>

#include "hecal/report/html_report.h"

namespace hecal::report {
namespace {

using nlohmann::json;

study::StudyResult SmallStudy(int trials) {
  study::StudyOptions options;
  for (const int stations : {3, 6}) {
    study::Setting setting;
    setting.stations = stations;
    setting.translation_sigma = 3e-4;
    setting.rotation_sigma = 3e-4;
    options.settings.push_back(setting);
  }
  options.methods = {estimation::Method::kAndreff, estimation::Method::kTsaiLenz};
  options.trials = trials;
  options.threads = 1;
  return study::RunStudy(options);
}

TEST(SimulatePage, OneEntryPerSettingAndMethodInDegreesAndMillimetres) {
  const study::StudyResult result = SmallStudy(4);
  const json data = SimulatePageData(result, "study.html");
  EXPECT_EQ(data["kind"], "simulate");
  EXPECT_EQ(data["title"], "study.html");
  EXPECT_EQ(data["methods"], json({"andreff", "tsai-lenz"}));
  ASSERT_EQ(data["settings"].size(), 2u);
  const json& first = data["settings"][0];
  EXPECT_EQ(first["stations"], 3);
  EXPECT_DOUBLE_EQ(first["sigma_mm"].get<double>(), 0.3);
  EXPECT_NE(first["label"].get<std::string>().find("3 stations"), std::string::npos);
  ASSERT_EQ(first["methods"].size(), 2u);
  const study::MethodSummary& m = result.summaries[0];
  EXPECT_NEAR(first["methods"][0]["rotation_deg"]["rmse"].get<double>(),
              m.rotation.rmse * 180.0 / std::numbers::pi, 1e-12);
  EXPECT_NEAR(first["methods"][0]["translation_mm"]["rmse"].get<double>(),
              m.translation.rmse * 1000.0, 1e-12);
  EXPECT_FALSE(first["methods"][0].contains("consistency"));  // no covariance asked for
  // No gross outliers: the clean reference is NaN, written as null.
  EXPECT_TRUE(first["methods"][0]["rejection"]["rotation_rmse_clean_deg"].is_null());
  ASSERT_EQ(data["trials"].size(), 2u);
  ASSERT_EQ(data["trials"][1].size(), 2u);
  EXPECT_EQ(data["trials"][1][1]["rotation_deg"].size(), 4u);
  EXPECT_EQ(data["trials_total"], 4);
  EXPECT_FALSE(data["trials_sampled"].get<bool>());
  // The shell takes it: one page of kind simulate.
  const std::string page = FormatHtmlPage(data);
  EXPECT_NE(page.find("\"kind\":\"simulate\""), std::string::npos);
}

TEST(SimulatePage, ManyTrialsAreSampledEvenlyAndSaidSo) {
  const int trials = static_cast<int>(kMaxPlottedTrials) + 1;  // stride 2
  const json data = SimulatePageData(SmallStudy(trials), "t");
  EXPECT_TRUE(data["trials_sampled"].get<bool>());
  EXPECT_EQ(data["trials_total"], trials);
  for (const json& setting : data["trials"]) {
    for (const json& method : setting) {
      EXPECT_EQ(method["rotation_deg"].size(), (static_cast<size_t>(trials) + 1) / 2);
      EXPECT_LE(method["translation_mm"].size(), kMaxPlottedTrials);
    }
  }
  // The statistics use every trial.
  EXPECT_EQ(data["settings"][0]["methods"][0]["trials"], trials);
}

}  // namespace
}  // namespace hecal::report
