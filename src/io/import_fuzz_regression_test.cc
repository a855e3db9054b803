// Replays, through the same property check as the import fuzzers (testing/import_properties.h),
// every input they have flagged (tests/data/fuzz-regressions/import_{text,yaml,json}/) and their
// seed corpora (fuzz/corpus/import_*/). The byte layout is the fuzzer's (RunImportFuzzInput). A
// violated property aborts the test with the property's name.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "hecal/io/atomic_file.h"
#include "hecal/io/import_tabb.h"
#include "testing/import_properties.h"

namespace hecal::io {
namespace {

namespace fs = std::filesystem;
using testing::ImportFuzzer;

int Replay(const fs::path& dir, ImportFuzzer fuzzer) {
  std::vector<fs::path> paths;
  if (fs::is_directory(dir)) {
    for (const auto& entry : fs::directory_iterator(dir)) {
      if (entry.is_regular_file()) paths.push_back(entry.path());
    }
  }
  std::sort(paths.begin(), paths.end());
  for (const fs::path& path : paths) {
    SCOPED_TRACE(path.string());
    testing::RunImportFuzzInput(fuzzer, ReadFile(path.string()));
  }
  return static_cast<int>(paths.size());
}

TEST(ImportFuzzRegressionTest, KeptFuzzerFindingsStayFixed) {
  const fs::path root = fs::path(HECAL_SOURCE_DIR) / "tests/data/fuzz-regressions";
  EXPECT_GT(Replay(root / "import_text", ImportFuzzer::kText), 0);
  Replay(root / "import_yaml", ImportFuzzer::kYaml);
  Replay(root / "import_json", ImportFuzzer::kJson);
}

TEST(ImportFuzzRegressionTest, SeedCorporaReplayWithoutViolations) {
  const fs::path corpus = fs::path(HECAL_SOURCE_DIR) / "fuzz/corpus";
  EXPECT_GE(Replay(corpus / "import_text", ImportFuzzer::kText), 1);
  EXPECT_GE(Replay(corpus / "import_yaml", ImportFuzzer::kYaml), 1);
  EXPECT_GE(Replay(corpus / "import_json", ImportFuzzer::kJson), 1);
}

// The finding itself, stated: a cali.txt image name that is only a folder has no stem to pair
// the robot block with, and is refused with the line.
TEST(ImportFuzzRegressionTest, TabbImageNameWithoutStemIsRefused) {
  const std::string robot = "1\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n";
  const std::string camera = "1\nimages/ 1000 0 320 0 1000 240 0 0 1 1 0 0 0 1 0 0 0 1 0 0 500 0 0 0 0 0 0 0 0\n";
  try {
    ParseTabb(robot, "robot_cali.txt", camera, "cali.txt");
    FAIL() << "accepted an image name without a file name";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("cali.txt:2"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("has no file name"), std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace hecal::io
