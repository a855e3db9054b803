// Replays, through the same property check as the fuzzer (testing/pose_table_properties.h), every
// input the pose-table fuzzer has flagged (tests/data/fuzz-regressions/pose_table/) and its seed
// corpus (fuzz/corpus/pose_table/). A file's first byte is the reader options, as in
// fuzz/fuzz_pose_table.cc. A violated property aborts the test with the property's name.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "hecal/io/atomic_file.h"
#include "testing/pose_table_properties.h"

namespace hecal::io {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> Inputs(const fs::path& dir) {
  std::vector<fs::path> paths;
  if (!fs::is_directory(dir)) return paths;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.is_regular_file() && entry.path().filename() != "README.md") {
      paths.push_back(entry.path());
    }
  }
  std::sort(paths.begin(), paths.end());
  return paths;
}

int Replay(const fs::path& dir, int* accepted) {
  int count = 0;
  for (const fs::path& path : Inputs(dir)) {
    SCOPED_TRACE(path.string());
    const std::string bytes = ReadFile(path.string());
    if (bytes.empty()) continue;
    const std::string_view text = std::string_view(bytes).substr(1);
    const PoseReadOptions options =
        testing::PoseReadOptionsFromByte(static_cast<uint8_t>(bytes[0]));
    if (testing::CheckPoseTableProperties(text, options)) ++*accepted;
    ++count;
  }
  return count;
}

TEST(PoseTableFuzzRegressionTest, KeptFuzzerFindingsStayFixed) {
  int accepted = 0;
  const int count =
      Replay(fs::path(HECAL_SOURCE_DIR) / "tests/data/fuzz-regressions/pose_table", &accepted);
  EXPECT_GT(count, 0);
  std::printf("%d regression inputs, %d parse\n", count, accepted);
}

TEST(PoseTableFuzzRegressionTest, SeedCorpusParsesAndRoundTrips) {
  int accepted = 0;
  const int count = Replay(fs::path(HECAL_SOURCE_DIR) / "fuzz/corpus/pose_table", &accepted);
  EXPECT_GE(count, 10);
  EXPECT_EQ(accepted, count);  // every seed is a valid table
}

}  // namespace
}  // namespace hecal::io
