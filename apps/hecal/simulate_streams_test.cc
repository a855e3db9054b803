// `hecal simulate --streams` (docs/streams.md#the-study): the study's table and files, and its
// written recording calibrated back with `calibrate --streams` against its truth.json.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "cli_test_util.h"

namespace hecal::cli {
namespace {

using cli_test::CliTest;
using cli_test::Hecal;
using ::testing::HasSubstr;

using SimulateStreamsTest = CliTest;

TEST_F(SimulateStreamsTest, StudyAndRecordingRoundTrip) {
  std::filesystem::create_directories(Path("rec"));
  const cli_test::Outcome study =
      Hecal({"simulate", "--streams", "--trials", "2", "--threads", "2", "--sigma", "0.1",
             "--duration", "20", "--write-streams", Path("rec"), "--output", Path("trials.csv")});
  ASSERT_EQ(study.code, 0) << study.err;
  EXPECT_THAT(study.out, HasSubstr("offset RMS"));
  EXPECT_THAT(Read("trials.csv"), HasSubstr("true_offset_s,offset_error_s,offset_sigma_s"));
  const nlohmann::json truth = nlohmann::json::parse(Read("rec/truth.json"));
  const cli_test::Outcome fit =
      Hecal({"calibrate", "--robot", Path("rec/robot.csv"), "--camera", Path("rec/camera.csv"),
             "--streams", "--setup", "eye-in-hand", "--output", Path("fit.json")});
  ASSERT_EQ(fit.code, 0) << fit.err;
  const nlohmann::json result = nlohmann::json::parse(Read("fit.json"));
  EXPECT_NEAR(result["time_offset"]["seconds"].get<double>(), truth["time_offset"].get<double>(),
              0.002);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(result["X"]["translation"][k].get<double>(),
                truth["X"]["translation"][k].get<double>(), 0.002);
  }
}

TEST_F(SimulateStreamsTest, WriteStreamsNeedsAnExistingFolderBeforeTheStudyRuns) {
  const cli_test::Outcome run =
      Hecal({"simulate", "--streams", "--trials", "200", "--write-streams", Path("missing/dir")});
  EXPECT_EQ(run.code, 2);
  EXPECT_THAT(run.err, HasSubstr("--write-streams"));
  EXPECT_THAT(run.err, HasSubstr("does not exist"));
}

}  // namespace
}  // namespace hecal::cli
