#include "hecal/io/atomic_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

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

// The message of the InputError `write` throws ("" when it throws none).
template <typename F>
std::string AtomicFileError(F write) {
  try {
    write();
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST_F(AtomicFileTest, ASymbolicLinkIsWrittenThroughAndStaysALink) {
  const fs::path real = dir_ / "real.csv";
  WriteFileAtomically(real.string(), "old\n");
  fs::permissions(real, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  fs::create_symlink("real.csv", dir_ / "link.csv");
  WriteFileAtomically((dir_ / "link.csv").string(), "new\n");
  EXPECT_TRUE(fs::is_symlink(dir_ / "link.csv"));
  EXPECT_EQ(ReadFile(real.string()), "new\n");
  EXPECT_EQ(fs::status(real).permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  EXPECT_EQ(Entries(), (std::vector<std::string>{"link.csv", "real.csv"}));
}

TEST_F(AtomicFileTest, ABrokenLinkAFifoAndADeviceAreRefusedAndKept) {
  fs::create_symlink("nowhere.csv", dir_ / "broken.csv");
  EXPECT_THAT(AtomicFileError([&] { WriteFileAtomically((dir_ / "broken.csv").string(), "x"); }),
              HasSubstr("broken link"));
  ASSERT_EQ(mkfifo((dir_ / "pipe").c_str(), 0600), 0);
  EXPECT_THAT(AtomicFileError([&] { WriteFileAtomically((dir_ / "pipe").string(), "x"); }),
              HasSubstr("FIFO"));
  EXPECT_TRUE(fs::is_fifo(dir_ / "pipe"));
  EXPECT_THAT(AtomicFileError([&] { ReadFile((dir_ / "pipe").string()); }), HasSubstr("FIFO"));
  fs::create_symlink("/dev/null", dir_ / "null");
  EXPECT_THAT(AtomicFileError([&] { WriteFileAtomically((dir_ / "null").string(), "x"); }),
              HasSubstr("character device"));
  EXPECT_THAT(AtomicFileError([&] { WriteFileAtomically("/dev/null", "x"); }),
              HasSubstr("character device"));
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
  EXPECT_THAT(AtomicFileError([&] { ReadFile("/dev/zero"); }), HasSubstr("character device"));
  EXPECT_EQ(Entries(), (std::vector<std::string>{"broken.csv", "null", "pipe"}));
}

TEST_F(AtomicFileTest, AnOutputThatIsAnInputIsRefusedHardLinksIncluded) {
  const std::string input = (dir_ / "in.csv").string();
  WriteFileAtomically(input, "data\n");
  fs::create_hard_link(input, dir_ / "alias.csv");
  for (const std::string& output :
       {input, (dir_ / "." / "in.csv").string(), (dir_ / "alias.csv").string()}) {
    EXPECT_THAT(AtomicFileError([&] {
                  CheckOutputs({{"--output", output}}, {{"--robot", input}});
                }),
                HasSubstr("names the input --robot"))
        << output;
  }
  EXPECT_THAT(AtomicFileError([&] {
                CheckOutputs({{"--output", (dir_ / "a.csv").string()},
                              {"--summary", (dir_ / "." / "a.csv").string()}},
                             {});
              }),
              HasSubstr("same file as --output"));
  EXPECT_EQ(AtomicFileError([&] {
              CheckOutputs({{"--output", (dir_ / "new.csv").string()}, {"--x", ""}},
                           {{"--robot", input}});
            }),
            "");
  EXPECT_EQ(ReadFile(input), "data\n");
}

TEST_F(AtomicFileTest, SeveralFilesAreWrittenAllOrNone) {
  const std::string kept = (dir_ / "kept.csv").string();
  WriteFileAtomically(kept, "previous\n");
  // The second target's directory is missing: nothing is written, the first file keeps its text.
  EXPECT_THAT(AtomicFileError([&] {
                WriteFilesAtomically({{"--output", kept, "new\n"},
                                      {"--summary", (dir_ / "no" / "s.csv").string(), "s\n"}});
              }),
              HasSubstr("does not exist"));
  EXPECT_EQ(ReadFile(kept), "previous\n");
  EXPECT_EQ(Entries(), std::vector<std::string>{"kept.csv"});
  // A rename that fails after the first succeeded (the second target became a directory after
  // staging) puts the first file back.
  fs::create_directories(dir_ / "late");
  {
    StagedFiles staged;
    staged.Stage("--output", kept, "new\n");
    fs::remove(dir_ / "late");
    staged.Stage("--summary", (dir_ / "late").string(), "s\n");
    fs::create_directories(dir_ / "late" / "inside");
    EXPECT_THROW(staged.Commit(), InputError);
  }
  EXPECT_EQ(ReadFile(kept), "previous\n");
  EXPECT_EQ(Entries(), (std::vector<std::string>{"kept.csv", "late"}));
  WriteFilesAtomically(
      {{"--output", kept, "new\n"}, {"--summary", (dir_ / "s.csv").string(), "s\n"}});
  EXPECT_EQ(ReadFile(kept), "new\n");
  EXPECT_EQ(ReadFile((dir_ / "s.csv").string()), "s\n");
  EXPECT_EQ(Entries(), (std::vector<std::string>{"kept.csv", "late", "s.csv"}));
}

// StagedFolder: the files appear together at Commit; a failure midway (an exception after some
// files were staged) leaves no trace: no new folder, not even a created parent, and an existing
// folder exactly as it was.
TEST_F(AtomicFileTest, AFolderOfFilesAppearsAtCommit) {
  const fs::path folder = dir_ / "a" / "b";
  {
    StagedFolder staged("--output", folder.string());
    staged.Stage("one.txt", "1\n");
    staged.Stage("two.txt", "2\n");
    EXPECT_FALSE(fs::exists(folder / "one.txt"));  // staged, not yet in place
    staged.Commit();
  }
  EXPECT_EQ(ReadFile((folder / "one.txt").string()), "1\n");
  EXPECT_EQ(ReadFile((folder / "two.txt").string()), "2\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(folder), fs::directory_iterator()), 2);
}

TEST_F(AtomicFileTest, AFolderWriteThatFailsMidwayLeavesNothing) {
  const fs::path folder = dir_ / "new" / "frames";
  EXPECT_THROW(
      {
        StagedFolder staged("--output", folder.string());
        staged.Stage("frame_0000.png", "first");
        EXPECT_TRUE(fs::is_directory(folder));
        throw InputError("frame_0001.png", 0, "cannot encode", "a smaller image");
      },
      InputError);
  EXPECT_EQ(Entries(), std::vector<std::string>{});  // "new" is gone too

  // An existing folder keeps its files, and gets none of the failed write's.
  const fs::path existing = dir_ / "existing";
  fs::create_directories(existing);
  WriteFileAtomically((existing / "one.txt").string(), "before\n");
  {
    StagedFolder staged("--output", existing.string());
    staged.Stage("one.txt", "after\n");
    staged.Stage("two.txt", "2\n");
    EXPECT_THROW(staged.Stage("one.txt", "again\n"), InputError);  // the same file twice
  }
  EXPECT_EQ(ReadFile((existing / "one.txt").string()), "before\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(existing), fs::directory_iterator()), 1);
}

TEST_F(AtomicFileTest, AFolderPathThatIsAFileIsRefused) {
  const std::string file = (dir_ / "file").string();
  WriteFileAtomically(file, "kept\n");
  StagedFolder staged("--output", file, "the frames");
  const std::string error = AtomicFileError([&] { staged.Stage("x.txt", "x"); });
  EXPECT_THAT(error, HasSubstr("cannot write the frames: it exists and is not a folder"));
  EXPECT_THAT(error, HasSubstr("give --output a folder"));
  EXPECT_EQ(ReadFile(file), "kept\n");
}

}  // namespace
}  // namespace hecal::io
