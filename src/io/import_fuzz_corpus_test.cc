// Replays the import fuzzers' seed corpora (fuzz/corpus/import_*) and a few adversarial inputs
// through the same property check the fuzzers run (testing/import_properties.h), so the unit
// tests catch a reader that crashes, throws anything but InputError, or accepts a broken pose.
// Add any input a fuzzer finds to crash to fuzz/corpus/import_<reader>/ and it is replayed here.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "hecal/io/atomic_file.h"
#include "testing/import_properties.h"

namespace hecal::io {
namespace {

namespace fs = std::filesystem;
using testing::ImportReader;

// The fuzzers' input layouts: fuzz/fuzz_import_{yaml,json,text}.cc.
void Replay(const std::string& corpus, const std::string& input) {
  if (corpus == "import_json") {
    testing::RunImportProperty(ImportReader::kMoveit, 0, input);
    return;
  }
  if (input.empty()) return;
  const unsigned char selector = static_cast<unsigned char>(input[0]);
  const std::string_view text = std::string_view(input).substr(1);
  if (corpus == "import_yaml") {
    constexpr ImportReader kReaders[] = {ImportReader::kCamodocal, ImportReader::kEasyHandeye,
                                         ImportReader::kOpenCvYaml};
    testing::RunImportProperty(kReaders[selector % 3], static_cast<unsigned char>(selector / 3),
                               text);
  } else {
    constexpr ImportReader kReaders[] = {ImportReader::kTabb, ImportReader::kEthz,
                                         ImportReader::kMatrix16};
    testing::RunImportProperty(kReaders[selector % 3], static_cast<unsigned char>(selector / 3),
                               text);
  }
}

TEST(ImportFuzzCorpus, EverySeedKeepsTheProperties) {
  const fs::path root = fs::path(HECAL_SOURCE_DIR) / "fuzz" / "corpus";
  int replayed = 0;
  for (const char* corpus : {"import_yaml", "import_json", "import_text"}) {
    ASSERT_TRUE(fs::is_directory(root / corpus)) << root / corpus;
    for (const fs::directory_entry& entry : fs::directory_iterator(root / corpus)) {
      SCOPED_TRACE(entry.path().string());
      Replay(corpus, ReadFile(entry.path().string()));
      ++replayed;
    }
  }
  EXPECT_GE(replayed, 12);
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
