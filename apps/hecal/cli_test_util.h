// Test support for the CLI tests: run `hecal` in-process through RunHecal (capturing stdout,
// stderr and the exit code) inside a fresh per-test temporary directory; the repository's data/
// folder; a pose read back from a result file.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Core>
#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli.h"
#include "hecal/hecal.h"

namespace hecal::cli::cli_test {

// The repository's data/ folder (the public datasets and examples), with its trailing slash.
inline const std::string kData = std::string(HECAL_SOURCE_DIR) + "/data/";

// The pose of a result file's transform object (docs/result-file.md): its 4×4 "matrix".
inline Pose PoseOf(const nlohmann::json& object) {
  Eigen::Matrix4d M;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) M(r, c) = object["matrix"][r][c].get<double>();
  }
  return Pose(M);
}

struct Outcome {
  int code = 0;
  std::string out;
  std::string err;
};

inline Outcome Hecal(const std::vector<std::string>& args) {
  std::vector<std::string> argv = {"hecal"};
  argv.insert(argv.end(), args.begin(), args.end());
  std::ostringstream out, err;
  const int code = RunHecal(argv, out, err);
  return {code, out.str(), err.str()};
}

// A fixture with its own directory, removed after the test.
class CliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("hecal_cli_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->test_suite_name() + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::string Path(const std::string& name) const { return (dir_ / name).string(); }
  std::string Write(const std::string& name, const std::string& contents) const {
    io::WriteFileAtomically(Path(name), contents);
    return Path(name);
  }
  std::string Read(const std::string& name) const { return io::ReadFile(Path(name)); }

  // The input-error contract (docs/cli.md#exit-codes-and-errors) of a run refused at `flag`:
  // exit 2, one line on stderr, "hecal: FLAG: ..." holding `problem` and naming the flag, not the
  // options field ("Options."), nothing on stdout, and `output` (a name in the test folder) not
  // written.
  void ExpectRefused(const std::vector<std::string>& args, const std::string& flag,
                     const std::string& problem, const std::string& output) const {
    const Outcome run = Hecal(args);
    EXPECT_EQ(run.code, 2) << run.err;
    EXPECT_EQ(run.err.rfind("hecal: " + flag + ": ", 0), 0u) << run.err;
    EXPECT_NE(run.err.find(problem), std::string::npos) << run.err;
    EXPECT_EQ(run.err.find("Options."), std::string::npos) << run.err;  // a flag, not a field
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_TRUE(run.out.empty()) << run.out;
    EXPECT_FALSE(std::filesystem::exists(Path(output))) << output;
  }

  // The same contract with the whole line: stderr is exactly "hecal: " + line + "\n".
  void ExpectRefusedLine(const std::vector<std::string>& args, const std::string& line,
                         const std::string& output) const {
    const Outcome run = Hecal(args);
    EXPECT_EQ(run.code, 2) << run.err;
    EXPECT_EQ(run.err, "hecal: " + line + "\n");
    EXPECT_TRUE(run.out.empty()) << run.out;
    EXPECT_FALSE(std::filesystem::exists(Path(output))) << output;
  }

  std::filesystem::path dir_;
};

}  // namespace hecal::cli::cli_test
