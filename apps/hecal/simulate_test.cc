// `hecal simulate` through RunHecal: flags, files, exit codes.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_test_util.h"

namespace hecal::cli {
namespace {

using cli_test::Hecal;
using cli_test::Outcome;
using SimulateCommand = cli_test::CliTest;

TEST_F(SimulateCommand, WritesTrialsAndSummaryAndPrintsATable) {
  const Outcome run =
      Hecal({"simulate", "--stations", "5", "--trials", "4", "--sigma", "0.1,0.2/0.05", "--method",
             "park-martin,ml", "--setup", "eye-in-hand,eye-to-hand", "--output", Path("trials.csv"),
             "--summary", Path("summary.csv")});
  ASSERT_EQ(run.code, 0) << run.err;
  const std::string trials = Read(("trials.csv"));
  const std::string summary = Read(("summary.csv"));
  // 2 setups × 2 sigma levels × 1 station count = 4 settings; × 4 trials × 2 methods.
  EXPECT_EQ(std::count(trials.begin(), trials.end(), '\n'), 1 + 4 * 4 * 2);
  EXPECT_EQ(std::count(summary.begin(), summary.end(), '\n'), 1 + 4 * 2);
  EXPECT_NE(trials.find("\neye-to-hand,5,both,gaussian,0.2,0.05,3,ml,ok,"), std::string::npos);
  EXPECT_NE(summary.find("rotation_rmse_deg"), std::string::npos);
  EXPECT_NE(
      run.out.find("eye-to-hand, 5 stations, gaussian noise on both, sigma 0.2 mm / 0.05 deg"),
      std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("first-order bound"), std::string::npos);
  EXPECT_NE(run.out.find("park-martin"), std::string::npos);
}

TEST_F(SimulateCommand, SameSeedSameFileWhateverTheThreads) {
  const std::vector<std::string> common = {
      "simulate", "--stations",        "4,6",     "--trials", "5",          "--sigma", "0.3",
      "--method", "tsai-lenz,andreff", "--noise", "uniform",  "--noise-on", "camera",  "--seed",
      "7"};
  std::vector<std::string> one = common, two = common;
  one.insert(one.end(), {"--threads", "1", "--output", Path("one.csv")});
  two.insert(two.end(), {"--threads", "2", "--output", Path("two.csv")});
  ASSERT_EQ(Hecal(one).code, 0);
  ASSERT_EQ(Hecal(two).code, 0);
  const std::string a = Read(("one.csv"));
  EXPECT_FALSE(a.empty());
  EXPECT_EQ(a, Read(("two.csv")));
  EXPECT_NE(a.find(",camera,uniform,0.3,0.3,"), std::string::npos);
}

TEST_F(SimulateCommand, BadFlagsExitTwoWithOneLine) {
  const std::vector<std::vector<std::string>> bad = {
      {"simulate", "--stations", "2"},        {"simulate", "--stations", "5,,10"},
      {"simulate", "--stations", "five"},     {"simulate", "--sigma", "-1"},
      {"simulate", "--sigma", "1/x"},         {"simulate", "--method", "opencv"},
      {"simulate", "--noise", "pink"},        {"simulate", "--noise-on", "table"},
      {"simulate", "--setup", "eye-on-hand"}, {"simulate", "--trials", "0"},
      {"simulate", "--threads", "-2"},
  };
  for (const std::vector<std::string>& args : bad) {
    const Outcome run = Hecal(args);
    EXPECT_EQ(run.code, 2) << args.back();
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  }
  // A missing output directory: exit 2 and no file.
  const Outcome run = Hecal({"simulate", "--stations", "3", "--trials", "1", "--method", "andreff",
                             "--output", Path("missing/dir/trials.csv")});
  EXPECT_EQ(run.code, 2) << run.err;
  EXPECT_FALSE(std::filesystem::exists(Path("missing/dir/trials.csv")));
}

// --report writes the page with the CSV files, or nothing: a page in a missing directory leaves
// the CSV unwritten too.
TEST_F(SimulateCommand, ReportIsWrittenWithTheOtherFilesOrNotAtAll) {
  const std::vector<std::string> common = {"simulate", "--stations", "3,5",      "--trials",  "3",
                                           "--sigma",  "0.3",        "--method", "andreff,ml"};
  std::vector<std::string> good = common, bad = common;
  good.insert(good.end(), {"--summary", Path("summary.csv"), "--report", Path("study.html")});
  const Outcome run = Hecal(good);
  ASSERT_EQ(run.code, 0) << run.err;
  const std::string page = Read("study.html");
  EXPECT_NE(page.find("\"kind\":\"simulate\""), std::string::npos);
  EXPECT_NE(page.find("hecalPage.pages.simulate"), std::string::npos);
  EXPECT_NE(run.out.find("wrote the page to"), std::string::npos) << run.out;
  bad.insert(bad.end(), {"--summary", Path("other.csv"), "--report", Path("missing/study.html")});
  const Outcome refused = Hecal(bad);
  EXPECT_EQ(refused.code, 2);
  EXPECT_EQ(std::count(refused.err.begin(), refused.err.end(), '\n'), 1) << refused.err;
  EXPECT_NE(refused.err.find("--report"), std::string::npos) << refused.err;
  EXPECT_FALSE(std::filesystem::exists(Path("other.csv")));
}

// The stream study has no page: --report with --streams exits 2 and writes nothing.
TEST_F(SimulateCommand, ReportIsRefusedWithStreams) {
  const Outcome run =
      Hecal({"simulate", "--streams", "--trials", "1", "--report", Path("streams.html")});
  EXPECT_EQ(run.code, 2) << run.err;
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  EXPECT_NE(run.err.find("--report"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(Path("streams.html")));
}

}  // namespace
}  // namespace hecal::cli
