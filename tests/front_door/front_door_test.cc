// The front door is the only door: the command line (apps/hecal, its tests aside), the examples
// and the Python module's C++ include nothing of hecal but the umbrella hecal/hecal.h
// (docs/architecture.md#layers), so everything they reach is the public API.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
const fs::path kRepositoryRoot = HECAL_SOURCE_DIR;

bool IsSource(const fs::path& path) {
  const std::string extension = path.extension().string();
  return extension == ".cc" || extension == ".h";
}

bool IsTest(const fs::path& path) {
  const std::string stem = path.stem().string();
  return stem.ends_with("_test") || stem.ends_with("_test_util");
}

// "file:line: #include ..." for every include of a hecal header other than hecal/hecal.h in the
// non-test sources under `folder`.
std::vector<std::string> SideDoors(const fs::path& folder) {
  static const std::regex kInclude(R"(^\s*#\s*include\s*[<"](hecal/[^">]+)[">])");
  std::vector<std::string> found;
  if (!fs::exists(folder)) return found;
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(folder)) {
    if (!entry.is_regular_file() || !IsSource(entry.path()) || IsTest(entry.path())) continue;
    std::ifstream in(entry.path());
    int number = 0;
    for (std::string line; std::getline(in, line);) {
      ++number;
      std::smatch match;
      if (std::regex_search(line, match, kInclude) && match[1] != "hecal/hecal.h") {
        found.push_back(fs::relative(entry.path(), kRepositoryRoot).string() + ":" +
                        std::to_string(number) + ": " + line);
      }
    }
  }
  return found;
}

TEST(FrontDoor, CommandLineExamplesAndPythonIncludeOnlyTheUmbrella) {
  int scanned = 0;
  for (const char* folder : {"apps/hecal", "examples", "python"}) {
    if (fs::exists(kRepositoryRoot / folder)) ++scanned;
    for (const std::string& door : SideDoors(kRepositoryRoot / folder)) ADD_FAILURE() << door;
  }
  EXPECT_GE(scanned, 2);  // apps/hecal and examples at least
}

// The scan itself finds a side door: this very file's pattern on a line that has one.
TEST(FrontDoor, TheScanSeesAnInclude) {
  const fs::path scratch = fs::temp_directory_path() / "hecal_front_door_scan";
  fs::create_directories(scratch);
  std::ofstream(scratch / "cli.cc") << "#include \"hecal/hecal.h\"\n#include <hecal/io/units.h>\n";
  std::ofstream(scratch / "cli_test.cc") << "#include \"hecal/io/units.h\"\n";
  const std::vector<std::string> found = SideDoors(scratch);
  fs::remove_all(scratch);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_NE(found[0].find("cli.cc:2"), std::string::npos) << found[0];
}

}  // namespace
