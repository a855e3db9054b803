// Replays the import fuzzers' seed corpora (fuzz/corpus/import_*) and a few adversarial inputs
// through the same property check the fuzzers run (testing/import_properties.h), so the unit
// tests catch a reader that crashes, throws anything but InputError, or accepts a broken pose.
// Inputs a fuzzer finds to fail go to tests/data/fuzz-regressions/import_<fuzzer>/ and are
// replayed here too.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "hecal/io/atomic_file.h"
#include "testing/import_properties.h"

namespace hecal::io {
namespace {

namespace fs = std::filesystem;
using testing::ImportFuzzer;
using testing::ImportReader;

// Replays every file of `dir` with the byte layout of `fuzzer` (RunImportFuzzInput); returns
// how many.
int ReplayFolder(const fs::path& dir, ImportFuzzer fuzzer) {
  int replayed = 0;
  if (!fs::is_directory(dir)) return 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    SCOPED_TRACE(entry.path().string());
    testing::RunImportFuzzInput(fuzzer, ReadFile(entry.path().string()));
    ++replayed;
  }
  return replayed;
}

TEST(ImportFuzzCorpus, EverySeedKeepsTheProperties) {
  const fs::path root = fs::path(HECAL_SOURCE_DIR) / "fuzz" / "corpus";
  const int replayed = ReplayFolder(root / "import_yaml", ImportFuzzer::kYaml) +
                       ReplayFolder(root / "import_json", ImportFuzzer::kJson) +
                       ReplayFolder(root / "import_text", ImportFuzzer::kText);
  EXPECT_GE(replayed, 12);
}

// Inputs a fuzzer flagged, kept in tests/data/fuzz-regressions/import_{text,yaml,json}/ (their
// README says what each found).
TEST(ImportFuzzCorpus, KeptFindingsStayFixed) {
  const fs::path root = fs::path(HECAL_SOURCE_DIR) / "tests" / "data" / "fuzz-regressions";
  EXPECT_GE(ReplayFolder(root / "import_text", ImportFuzzer::kText), 1);
  ReplayFolder(root / "import_yaml", ImportFuzzer::kYaml);
  ReplayFolder(root / "import_json", ImportFuzzer::kJson);
}

// The finding itself, stated: a cali.txt image name that is only a folder has no stem to pair
// the robot block with, and is refused with its line.
TEST(ImportFuzzCorpus, TabbImageNameWithoutStemIsRefused) {
  const std::string robot = "1\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n";
  const std::string camera =
      "1\nimages/ 1000 0 320 0 1000 240 0 0 1 1 0 0 0 1 0 0 0 1 0 0 500 0 0 0 0 0 0 0 0\n";
  try {
    ParseTabb(robot, "robot_cali.txt", camera, "cali.txt");
    FAIL() << "accepted an image name without a file name";
  } catch (const InputError& error) {
    const std::string what = error.what();
    EXPECT_NE(what.find("cali.txt:2"), std::string::npos) << what;
    EXPECT_NE(what.find("has no file name"), std::string::npos) << what;
  }
}

TEST(ImportFuzzCorpus, SeedsAreAccepted) {
  // The seeds are valid files: each imports (so the fuzzers start from inputs that get past the
  // syntax checks).
  const std::string root = std::string(HECAL_SOURCE_DIR) + "/fuzz/corpus/";
  const std::string camodocal = ReadFile(root + "import_yaml/camodocal_2_pairs").substr(1);
  EXPECT_EQ(ParseCamodocalPairs(camodocal, "seed").robot.rows.size(), 2u);
  const std::string moveit = ReadFile(root + "import_json/moveit_2_samples");
  EXPECT_EQ(ParseMoveitSamples(moveit, "seed").camera->rows.size(), 2u);
  const std::string tabb = ReadFile(root + "import_text/tabb_2_poses").substr(1);
  const size_t split = tabb.find('\x1e');
  EXPECT_EQ(ParseTabb(tabb.substr(0, split), "r", tabb.substr(split + 1), "c").robot.rows.size(),
            2u);
}

TEST(ImportFuzzCorpus, DeepNestingIsRejectedNotACrash) {
  // yaml-cpp limits its recursion (DeepRecursion); nlohmann parses iteratively. Both must end in
  // an InputError, not a stack overflow.
  testing::RunImportProperty(ImportReader::kCamodocal, 0, std::string(100000, '['));
  testing::RunImportProperty(ImportReader::kEasyHandeye, 0, [] {
    std::string text;
    for (int i = 0; i < 50000; ++i) text += "{a: ";
    return text;
  }());
  testing::RunImportProperty(ImportReader::kMoveit, 0, std::string(200000, '['));
  EXPECT_THROW(ParseMoveitSamples(std::string(200000, '['), "deep.json"), InputError);
  EXPECT_THROW(ParseCamodocalPairs(std::string(100000, '['), "deep.yml"), InputError);
}

}  // namespace
}  // namespace hecal::io
