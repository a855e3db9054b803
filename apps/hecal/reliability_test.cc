// The output rules and the recorded seed of docs/reliability.md, on the commands' success
// paths (the refusals are the corpus of robustness_test.cc): an output through a symbolic link
// replaces the file it points to and keeps the link; a multi-output command that fails after its
// first file was staged leaves nothing (contour render removes the folder it created); every
// output of a multi-output command is written when all can be; the seed is recorded where
// randomness was used (simulate, bench --json, contour study, contour render).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "cli_test_util.h"

namespace hecal::cli {
namespace {

namespace fs = std::filesystem;
using cli_test::Hecal;
using cli_test::Outcome;

class Reliability : public cli_test::CliTest {};

const std::string kPoses =
    "id,x,y,z,qw,qx,qy,qz\n1,0.1,0,0,1,0,0,0\n2,0,0.1,0,0.9950042,0.0998334,0,0\n";

TEST_F(Reliability, AnOutputThroughASymbolicLinkReplacesItsFileAndKeepsTheLink) {
  Write("in.csv", kPoses);
  fs::create_directories(dir_ / "kept");
  Write("kept/real.csv", "old\n");
  fs::create_symlink("kept/real.csv", dir_ / "link.csv");
  const Outcome run = Hecal({"poses", "convert", "--input", Path("in.csv"), "--output",
                             Path("link.csv"), "--to", "matrix"});
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_TRUE(fs::is_symlink(dir_ / "link.csv"));
  EXPECT_EQ(fs::read_symlink(dir_ / "link.csv"), fs::path("kept/real.csv"));
  EXPECT_NE(Read("kept/real.csv").find("r11"), std::string::npos) << Read("kept/real.csv");
  // No temporary file left in either folder.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_ / "kept"), fs::directory_iterator()), 1);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 3);
}

TEST_F(Reliability, SimulateWritesBothFilesAndPrintsItsSeed) {
  Write("trials.csv", "previous\n");
  const Outcome run = Hecal({"simulate", "--stations", "5", "--trials", "2", "--method",
                             "park-martin", "--seed", "18446744073709551615", "--output",
                             Path("trials.csv"), "--summary", Path("summary.csv")});
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_EQ(run.out.rfind("hecal simulate: seed 18446744073709551615\n", 0), 0u) << run.out;
  EXPECT_EQ(Read("trials.csv").rfind("setup,stations,", 0), 0u);
  EXPECT_EQ(Read("summary.csv").rfind("setup,stations,", 0), 0u);
}

TEST_F(Reliability, BenchAndContourStudyRecordTheirSeed) {
  const Outcome bench = Hecal({"bench", "--json", "--stations", "5", "--datasets", "2",
                               "--min-time", "0", "--method", "park-martin", "--seed", "7"});
  ASSERT_EQ(bench.code, 0) << bench.err;
  EXPECT_NE(bench.out.find("\"seed\": 7"), std::string::npos) << bench.out;

  const Outcome study =
      Hecal({"contour", "study", "--motion", "rx", "--from", "0", "--to", "10", "--steps", "2",
             "--samples", "50", "--seed", "3", "--output", Path("rx.csv")});
  ASSERT_EQ(study.code, 0) << study.err;
  EXPECT_EQ(Read("rx.csv").rfind("# hecal contour study: seed 3, 50 Monte Carlo samples", 0), 0u)
      << Read("rx.csv");
  EXPECT_NE(study.out.find("(seed 3)"), std::string::npos) << study.out;
}

#if defined(HECAL_HAVE_OPENCV_PEERS)
TEST_F(Reliability, ContourRenderWritesEveryFrameOrNoneAndRecordsItsSeed) {
  const std::vector<std::string> common = {"contour", "render", "--focal",  "800", "--z0",   "1000",
                                           "--size",  "64,64",  "--frames", "3",   "--seed", "5"};
  // The second frame puts the target behind the camera (Z0 + Tz = 0): the first, already
  // rendered, and the folder created for it are removed.
  std::vector<std::string> failing = common;
  failing.insert(failing.end(), {"--output", Path("new/frames"), "--to", "0,0,-2000,0,0,0"});
  const Outcome failed = Hecal(failing);
  EXPECT_EQ(failed.code, 2);
  EXPECT_NE(failed.err.find("in front of the camera"), std::string::npos) << failed.err;
  EXPECT_FALSE(fs::exists(dir_ / "new"));

  std::vector<std::string> good = common;
  good.insert(good.end(), {"--output", Path("frames"), "--to", "0,0,0,5,0,0"});
  const Outcome run = Hecal(good);
  ASSERT_EQ(run.code, 0) << run.err;
  for (const char* name :
       {"frame_0000.png", "frame_0001.png", "frame_0002.png", "init.csv", "truth.csv"}) {
    EXPECT_TRUE(fs::is_regular_file(dir_ / "frames" / name)) << name;
  }
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_ / "frames"), fs::directory_iterator()), 5);
  EXPECT_NE(Read("frames/truth.csv").find("noise seed 5\n"), std::string::npos);
}
#endif

}  // namespace
}  // namespace hecal::cli
