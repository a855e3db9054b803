// RenderContourSequence (contour_rendering.h): the frames come in order as PNG files of the
// requested size, the motion is the linear interpolation from `from` to `to`, the first view is
// the pinhole projection of the target at Z0 (principal point at the image centre), init.csv
// reads back as that view, truth.csv has a row per frame; a contour file's points are the target;
// frames where the target leaves the image are counted; a failure midway (the frame callback
// throwing) stops the job, and a folder written all or none (io::StagedFolder) is then gone.
#include "hecal/jobs/contour_rendering.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "hecal/contour/contour_study.h"
#include "hecal/io/atomic_file.h"
#include "hecal/io/contour_file.h"
#include "hecal/vision/image_read.h"
#include "testing/options_validity.h"
#include "testing/scratch_folder.h"

namespace hecal::jobs {
namespace {

namespace fs = std::filesystem;

class ContourRenderingTest : public testing::ScratchFolderTest {
 protected:
  ContourRenderingTest() : ScratchFolderTest("hecal_contour_rendering") {}

  // 5 frames of 160 × 120 px of the built-in target at 5 m, f = 1500 px, from (2, −1, −50 mm,
  // 1°, −2°, 3°) to (10, 5, −200 mm, 6°, 4°, 9°).
  static ContourRenderingOptions Options() {
    ContourRenderingOptions options;
    options.sequence.camera = {1500.0, 5000.0};
    options.sequence.frames = 5;
    options.sequence.from << 2, -1, -50, 1, -2, 3;
    options.sequence.to << 10, 5, -200, 6, 4, 9;
    options.sequence.width = 160;
    options.sequence.height = 120;
    options.sequence.render.quantize = true;
    return options;
  }
};

TEST_F(ContourRenderingTest, FramesMotionAndFilesAreThoseOfTheOptions) {
  ContourRenderingOptions options = Options();
  options.sequence.from.setZero();  // the first view: the target fronto-parallel at Z0
  io::StagedFolder folder("", (dir_ / "seq").string());
  std::vector<std::string> names;
  const ContourRendering result =
      RenderContourSequence(options, [&](const std::string& name, const std::string& png) {
        names.push_back(name);
        folder.Stage(name, png);
      });
  folder.Stage("init.csv", result.init_csv);
  folder.Commit();

  EXPECT_EQ(names, (std::vector<std::string>{"frame_0000.png", "frame_0001.png", "frame_0002.png",
                                             "frame_0003.png", "frame_0004.png"}));
  for (const std::string& name : names) {
    const cv::Mat image = vision::ReadGrayImage((dir_ / "seq" / name).string(), 8);
    EXPECT_EQ(image.cols, 160);
    EXPECT_EQ(image.rows, 120);
  }
  ASSERT_EQ(result.rendered.frames.size(), 5u);
  for (int t = 0; t < 5; ++t) {
    const Vector6d expected =
        options.sequence.from + (options.sequence.to - options.sequence.from) * t / 4.0;
    EXPECT_LT((result.rendered.frames[static_cast<std::size_t>(t)].motion - expected).norm(), 1e-9)
        << t;
  }
  EXPECT_EQ(result.rendered.outside, 0);

  // The first view: x = f p / Z0 + c, c the image centre, p the built-in target's points.
  const Eigen::Matrix2Xd target = contour::DefaultTarget();
  EXPECT_EQ(result.options.target, target);
  const Eigen::Matrix2Xd first = (1500.0 / 5000.0 * target).colwise() + Eigen::Vector2d(79.5, 59.5);
  EXPECT_LT((result.rendered.first_view - first).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_EQ(io::ReadContourFile((dir_ / "seq" / "init.csv").string()), result.rendered.first_view);

  // truth.csv: a comment, the header and one row per frame, each naming its image.
  EXPECT_EQ(std::count(result.truth_csv.begin(), result.truth_csv.end(), '\n'), 7);
  for (const std::string& name : names) {
    EXPECT_NE(result.truth_csv.find("," + name + ","), std::string::npos) << name;
  }
}

TEST_F(ContourRenderingTest, AContourFileIsTheTargetAndLeavingTheImageIsCounted) {
  ContourRenderingOptions options = Options();
  options.contour = Write("square.csv", "x,y\n-200,-200\n200,-200\n200,200\n-200,200\n");
  options.sequence.to << 2500, 0, 0, 0, 0, 0;  // 2.5 m sideways at 5 m: out of a 160 px image
  const ContourRendering result = RenderContourSequence(options, {});
  Eigen::Matrix2Xd square(2, 4);
  square << -200, 200, 200, -200, -200, -200, 200, 200;
  EXPECT_EQ(result.options.target, square);
  EXPECT_FALSE(result.rendered.frames.front().outside);
  EXPECT_TRUE(result.rendered.frames.back().outside);
  EXPECT_EQ(result.rendered.outside,
            std::count_if(result.rendered.frames.begin(), result.rendered.frames.end(),
                          [](const contour::RenderedFrame& frame) { return frame.outside; }));
}

TEST_F(ContourRenderingTest, AFailureMidwayStopsTheJobAndTheFolderIsGone) {
  int frames = 0;
  EXPECT_THROW(
      {
        io::StagedFolder folder("", (dir_ / "new" / "seq").string());
        RenderContourSequence(Options(), [&](const std::string& name, const std::string& png) {
          if (++frames == 3) throw std::runtime_error("disk full");
          folder.Stage(name, png);
        });
      },
      std::runtime_error);
  EXPECT_EQ(frames, 3);  // no frame rendered after the failure
  EXPECT_FALSE(fs::exists(dir_ / "new"));
}

TEST(ContourRenderingOptionsTest, IsValidNamesTheField) {
  ContourRenderingOptions options;
  options.sequence.width = 64;
  options.sequence.height = 48;
  EXPECT_TRUE(testing::IsValidOptions(options));  // the built-in target
  EXPECT_TRUE(testing::RefusesNaming(options, "SequenceRenderOptions.frames",
                                     [](ContourRenderingOptions& o) { o.sequence.frames = 0; }));
  EXPECT_TRUE(testing::RefusesNaming(options, "SequenceRenderOptions.size",
                                     [](ContourRenderingOptions& o) { o.sequence.width = 4; }));
  EXPECT_TRUE(testing::RefusesNaming(
      options, "RenderOptions.blur_sigma",
      [](ContourRenderingOptions& o) { o.sequence.render.blur_sigma = 50; }));
  EXPECT_TRUE(testing::RefusesNaming(
      options, "SequenceRenderOptions.target",
      [](ContourRenderingOptions& o) { o.sequence.target = Eigen::Matrix2Xd::Zero(2, 3); }));
  // A contour file's points replace the target: its 3 points are the reader's to refuse.
  options.sequence.target = Eigen::Matrix2Xd::Zero(2, 3);
  options.contour = "target.csv";
  EXPECT_TRUE(testing::IsValidOptions(options));
}

}  // namespace
}  // namespace hecal::jobs
