#include "hecal/io/atomic_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "hecal/core/error.h"

namespace hecal::io {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

class AtomicFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("hecal_atomic_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
            "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::vector<std::string> Entries() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_)) {
      names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
  }

  fs::path dir_;
};

TEST_F(AtomicFileTest, WritesAndReadsBack) {
  const std::string path = (dir_ / "out.csv").string();
  std::string contents = "x,y,z\n";
  contents.push_back('\0');
  contents += std::string(200000, 'a');
  WriteFileAtomically(path, contents);
  EXPECT_EQ(ReadFile(path), contents);
  EXPECT_EQ(Entries(), std::vector<std::string>{"out.csv"});  // no temporary left behind
}

TEST_F(AtomicFileTest, ReplacesAnExistingFile) {
  const std::string path = (dir_ / "out.csv").string();
  WriteFileAtomically(path, "old contents that are longer\n");
  WriteFileAtomically(path, "new\n");
  EXPECT_EQ(ReadFile(path), "new\n");
  EXPECT_EQ(Entries(), std::vector<std::string>{"out.csv"});
}

TEST_F(AtomicFileTest, EmptyContents) {
  const std::string path = (dir_ / "empty").string();
  WriteFileAtomically(path, "");
  EXPECT_EQ(ReadFile(path), "");
}

TEST_F(AtomicFileTest, MissingDirectoryIsAnInputErrorAndWritesNothing) {
  const std::string path = (dir_ / "no" / "such" / "out.csv").string();
  try {
    WriteFileAtomically(path, "x\n");
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.source(), path);
    EXPECT_THAT(error.what(), HasSubstr("does not exist"));
    EXPECT_THAT(error.what(), HasSubstr((dir_ / "no" / "such").string()));
  }
  EXPECT_TRUE(Entries().empty());
}

TEST_F(AtomicFileTest, DirectoryAsTargetIsAnInputError) {
  fs::create_directories(dir_ / "sub");
  EXPECT_THROW(WriteFileAtomically((dir_ / "sub").string(), "x"), InputError);
  EXPECT_EQ(Entries(), std::vector<std::string>{"sub"});
  EXPECT_TRUE(fs::is_directory(dir_ / "sub"));
}

TEST_F(AtomicFileTest, ConcurrentWritersNeverLeaveAPartialFile) {
  const std::string path = (dir_ / "shared.txt").string();
  const std::string a(100000, 'a');
  const std::string b(100000, 'b');
  std::thread writer_a([&] {
    for (int i = 0; i < 20; ++i) WriteFileAtomically(path, a);
  });
  std::thread writer_b([&] {
    for (int i = 0; i < 20; ++i) WriteFileAtomically(path, b);
  });
  writer_a.join();
  writer_b.join();
  const std::string result = ReadFile(path);
  EXPECT_TRUE(result == a || result == b);
  EXPECT_EQ(Entries(), std::vector<std::string>{"shared.txt"});
}

TEST_F(AtomicFileTest, ReadingAMissingFileIsAnInputError) {
  const std::string path = (dir_ / "missing.csv").string();
  try {
    ReadFile(path);
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.source(), path);
    EXPECT_EQ(error.line(), 0);
    EXPECT_THAT(error.what(), HasSubstr("cannot read"));
    EXPECT_THAT(error.what(), HasSubstr("fix:"));
  }
}

TEST_F(AtomicFileTest, ReadingADirectoryIsAnInputError) {
  EXPECT_THROW(ReadFile(dir_.string()), InputError);
}

}  // namespace
}  // namespace hecal::io
