// `hecal detect` end to end on synthetic images rendered (vision/render.h) with a known camera at
// known poses: the poses in camera.csv against the truth with given intrinsics, the estimated
// intrinsics (camera.yaml) against the true camera without them, the points file against the
// projected corners, the report; and bad input (exit 2, the file named, nothing written).
// Output files are read with the tests' own small CSV reader, quaternions turned into rotations
// with Eigen, independently of hecal's pose-table reader.
#include "detect.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli_test_util.h"

#if defined(HECAL_HAVE_OPENCV_PEERS)
#include <unistd.h>

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <numbers>
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "csv_test_util.h"
#include "hecal/pose/camera_model.h"
#include "hecal/pose/target.h"
#include "hecal/vision/render.h"
#include "rendered_views_test_util.h"
#endif

namespace hecal::cli {
namespace {

using cli_test::CliTest;
using cli_test::Hecal;

#if defined(HECAL_HAVE_OPENCV_PEERS)

using rendered_views::Board;
using rendered_views::CameraYaml;
using rendered_views::kDeg;
using rendered_views::kTargetYaml;
using rendered_views::RotationErrorDeg;
using rendered_views::TranslationErrorMm;
using rendered_views::TrueCamera;
using rendered_views::Views;

// Three views of a board parallel to the image plane, moved sideways and back.
std::vector<Pose> ParallelViews() {
  std::vector<Pose> views;
  for (int k = 0; k < 3; ++k) {
    views.push_back(MakePose(Eigen::Matrix3d::Identity(),
                             Eigen::Vector3d(-0.13 + 0.03 * k, -0.09, 0.4 + 0.05 * k)));
  }
  return views;
}

// Images are rendered once for the suite (slight blur and noise, as a real camera) and copied
// into each test's own folder.
class DetectTest : public CliTest {
 protected:
  static void SetUpTestSuite() {
    std::filesystem::create_directories(RenderDir());
    std::uint64_t seed = 1;
    const std::vector<Pose> views = Views();
    for (std::size_t i = 0; i < views.size(); ++i) {
      rendered_views::RenderView(views[i], ++seed, RenderDir() / ViewName(i));
    }
    const std::vector<Pose> parallel = ParallelViews();
    for (std::size_t i = 0; i < parallel.size(); ++i) {
      rendered_views::RenderView(parallel[i], ++seed,
                                 RenderDir() / ("parallel_" + std::to_string(i) + ".png"));
    }
  }
  static void TearDownTestSuite() { std::filesystem::remove_all(RenderDir()); }

  static std::filesystem::path RenderDir() {
    return std::filesystem::temp_directory_path() /
           ("hecal_detect_test_renders_" + std::to_string(::getpid()));
  }
  static std::string ViewName(std::size_t i) { return "view_0" + std::to_string(i) + ".png"; }

  // A folder `images` holding the named rendered images.
  std::string Images(const std::vector<std::string>& names) {
    const std::filesystem::path dir = dir_ / "images";
    std::filesystem::create_directories(dir);
    for (const std::string& name : names)
      std::filesystem::copy_file(RenderDir() / name, dir / name);
    return dir.string();
  }
  std::string FirstViews(std::size_t n) {
    std::vector<std::string> names;
    for (std::size_t i = 0; i < n; ++i) names.push_back(ViewName(i));
    return Images(names);
  }
  void Blank(const std::string& name, int width, int height) {
    cv::imwrite(Path(name), cv::Mat(height, width, CV_8UC1, cv::Scalar(128)));
  }

  std::string TargetFile() { return Write("target.yaml", kTargetYaml); }
};

Pose RowPose(const csv_test::Csv& csv, std::size_t row) {
  const Eigen::Quaterniond q(csv.Number(row, "qw"), csv.Number(row, "qx"), csv.Number(row, "qy"),
                             csv.Number(row, "qz"));
  return MakePose(
      q.normalized().toRotationMatrix(),
      Eigen::Vector3d(csv.Number(row, "x"), csv.Number(row, "y"), csv.Number(row, "z")));
}

TEST_F(DetectTest, PosesWithGivenIntrinsicsMatchTheRenderedTruth) {
  const pose::CameraModel camera = TrueCamera();
  const std::vector<Pose> all = Views();
  const std::vector<Pose> truth(all.begin(), all.begin() + 3);
  const std::string images = FirstViews(3);
  const cli_test::Outcome run =
      Hecal({"detect", "--images", images, "--target", TargetFile(), "--intrinsics",
             Write("camera.yaml", CameraYaml(camera)), "--output", Path("camera.csv")});
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_NE(run.out.find("view_02.png"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("found"), std::string::npos) << run.out;

  const csv_test::Csv poses = csv_test::ReadCsv(Path("camera.csv"));
  ASSERT_EQ(poses.rows.size(), truth.size());
  for (std::size_t i = 0; i < truth.size(); ++i) {
    EXPECT_EQ(poses.Text(i, "id"), "view_0" + std::to_string(i));
    // Sub-pixel corners (RMS ~0.03 px on a blurred, noisy 8-bit image) on a 0.2 m board at
    // 0.4 m: measured ≤ 0.015° and ≤ 0.02 mm (reported 1σ ~0.005°, ~0.01 mm).
    const Pose T = RowPose(poses, i);
    EXPECT_LT(RotationErrorDeg(T, truth[i]), 0.05) << i;
    EXPECT_LT(TranslationErrorMm(T, truth[i]), 0.1) << i;
  }

  // The points file: every corner of every image, each where the true pose projects it.
  const csv_test::Csv points = csv_test::ReadCsv(Path("camera.points.csv"));
  ASSERT_EQ(points.header, (std::vector<std::string>{"id", "point_id", "u", "v"}));
  ASSERT_EQ(points.rows.size(), truth.size() * 54);
  const std::vector<pose::ObjectPoint> board = pose::ObjectPoints(Board());
  double worst = 0.0;
  for (std::size_t r = 0; r < points.rows.size(); ++r) {
    const std::size_t view = static_cast<std::size_t>(points.Text(r, "id").back() - '0');
    const int id = std::stoi(points.Text(r, "point_id"));
    const Eigen::Vector2d expected =
        pose::Project(camera, truth[view] * board[static_cast<std::size_t>(id)].position);
    worst = std::max(
        worst, (Eigen::Vector2d(points.Number(r, "u"), points.Number(r, "v")) - expected).norm());
  }
  EXPECT_LT(worst, 0.3);
  EXPECT_FALSE(std::filesystem::exists(Path("camera.camera.yaml")));  // intrinsics were given
}

TEST_F(DetectTest, EstimatesTheIntrinsicsWhenNotGiven) {
  const pose::CameraModel camera = TrueCamera();
  const std::vector<Pose> truth = Views();
  const std::string images = FirstViews(truth.size());
  const cli_test::Outcome run = Hecal({"detect", "--images", images, "--target", TargetFile(),
                                       "--output", Path("camera.csv"), "--threads", "2"});
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_NE(run.out.find("intrinsics: estimated from 6 images"), std::string::npos) << run.out;

  // camera.yaml in hecal's layout, read as plain text: fx, fy, cx, cy near the truth. Measured:
  // within 0.45 px, with a reported 1σ of 0.2–0.3 px.
  const std::string yaml = Read("camera.camera.yaml");
  const auto value = [&yaml](const std::string& key) {
    const std::size_t at = yaml.find("\n" + key + ": ");
    EXPECT_NE(at, std::string::npos) << key << " missing in\n" << yaml;
    return std::stod(yaml.substr(at + key.size() + 3));
  };
  EXPECT_NEAR(value("fx"), camera.fx, 1.5);
  EXPECT_NEAR(value("fy"), camera.fy, 1.5);
  EXPECT_NEAR(value("cx"), camera.cx, 1.5);
  EXPECT_NEAR(value("cy"), camera.cy, 1.5);
  EXPECT_EQ(value("width"), 640);
  EXPECT_EQ(value("height"), 480);

  const csv_test::Csv poses = csv_test::ReadCsv(Path("camera.csv"));
  ASSERT_EQ(poses.rows.size(), truth.size());
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const Pose T = RowPose(poses, i);
    // Measured ≤ 0.03° and ≤ 0.3 mm (the estimated f is 0.07% short: depth 0.3 mm at 0.4 m).
    EXPECT_LT(RotationErrorDeg(T, truth[i]), 0.1) << i;
    EXPECT_LT(TranslationErrorMm(T, truth[i]), 1.0) << i;
  }
}

TEST_F(DetectTest, SkipsImagesWithoutTheTargetAndSaysWhy) {
  const pose::CameraModel camera = TrueCamera();
  const std::string images = FirstViews(3);
  Blank("images/view_99.png", 640, 480);
  Write("images/notes.txt", "not an image: ignored");
  const cli_test::Outcome run =
      Hecal({"detect", "--images", images, "--target", TargetFile(), "--intrinsics",
             Write("camera.yaml", CameraYaml(camera)), "--output", Path("camera.csv")});
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_NE(run.out.find("view_99.png"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("skipped"), std::string::npos) << run.out;
  EXPECT_EQ(csv_test::ReadCsv(Path("camera.csv")).rows.size(), 3u);
}

TEST_F(DetectTest, WrongBoardSizeSaysColsRowsAreInnerCorners) {
  const std::string images = FirstViews(1);
  // The squares (10 × 7) instead of the inner corners (9 × 6).
  const std::string target =
      Write("target.yaml", "type: chessboard\ncols: 10\nrows: 7\nsquare: 0.025\n");
  const cli_test::Outcome run =
      Hecal({"detect", "--images", images, "--target", target, "--output", Path("camera.csv")});
  EXPECT_EQ(run.code, 2);
  EXPECT_NE(run.err.find(target), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("INNER corners"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(Path("camera.csv")));
  EXPECT_FALSE(std::filesystem::exists(Path("camera.points.csv")));
  EXPECT_FALSE(std::filesystem::exists(Path("camera.camera.yaml")));
}

TEST_F(DetectTest, FewerThanThreeUsableImagesIsAnError) {
  const std::string images = FirstViews(2);
  Blank("images/view_99.png", 640, 480);
  const cli_test::Outcome run = Hecal(
      {"detect", "--images", images, "--target", TargetFile(), "--output", Path("camera.csv")});
  EXPECT_EQ(run.code, 2);
  EXPECT_NE(run.err.find("only 2 of the 3"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("at least 3"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(Path("camera.csv")));
}

TEST_F(DetectTest, BadImagesAndFoldersAreErrors) {
  // Missing folder.
  cli_test::Outcome run = Hecal({"detect", "--images", Path("nowhere"), "--target", TargetFile(),
                                 "--output", Path("camera.csv")});
  EXPECT_EQ(run.code, 2);
  EXPECT_NE(run.err.find(Path("nowhere")), std::string::npos) << run.err;

  // A folder without images.
  std::filesystem::create_directories(dir_ / "empty");
  Write("empty/readme.txt", "no images here");
  run = Hecal({"detect", "--images", Path("empty"), "--target", TargetFile(), "--output",
               Path("camera.csv")});
  EXPECT_EQ(run.code, 2);
  EXPECT_NE(run.err.find("no images"), std::string::npos) << run.err;

  // An unreadable image: named in the message.
  std::filesystem::create_directories(dir_ / "broken");
  Write("broken/broken.png", "this is not a PNG");
  run = Hecal({"detect", "--images", Path("broken"), "--target", TargetFile(), "--output",
               Path("camera.csv")});
  EXPECT_EQ(run.code, 2);
  EXPECT_NE(run.err.find("broken.png"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("cannot read"), std::string::npos) << run.err;

  // Images of two sizes: the odd one named.
  std::filesystem::create_directories(dir_ / "sizes");
  Blank("sizes/a.png", 640, 480);
  Blank("sizes/b.png", 640, 400);
  run = Hecal({"detect", "--images", Path("sizes"), "--target", TargetFile(), "--output",
               Path("camera.csv")});
  EXPECT_EQ(run.code, 2);
  EXPECT_NE(run.err.find("b.png"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("640x400"), std::string::npos) << run.err;

  // Intrinsics of another resolution.
  std::filesystem::remove(Path("sizes/b.png"));
  pose::CameraModel other = TrueCamera();
  other.width = 1280;
  other.height = 960;
  const std::string camera_file = Write("camera.yaml", CameraYaml(other));
  run = Hecal({"detect", "--images", Path("sizes"), "--target", TargetFile(), "--intrinsics",
               camera_file, "--output", Path("camera.csv")});
  EXPECT_EQ(run.code, 2);
  EXPECT_NE(run.err.find(camera_file), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("1280x960"), std::string::npos) << run.err;

  // A bad camera.yaml is reported before the images are read.
  const std::string bad_camera = Write("bad_camera.yaml", "fx: -1\nfy: 600\ncx: 320\ncy: 240\n");
  run = Hecal({"detect", "--images", Path("nowhere"), "--target", TargetFile(), "--intrinsics",
               bad_camera, "--output", Path("camera.csv")});
  EXPECT_EQ(run.code, 2);
  EXPECT_NE(run.err.find(bad_camera), std::string::npos) << run.err;

  // A missing output directory is reported before any work.
  run = Hecal({"detect", "--images", Path("sizes"), "--target", TargetFile(), "--output",
               Path("no/such/dir/camera.csv")});
  EXPECT_EQ(run.code, 2);
  EXPECT_NE(run.err.find("does not exist"), std::string::npos) << run.err;

  run = Hecal({"detect", "--images", Path("sizes"), "--target", TargetFile(), "--output",
               Path("camera.csv"), "--threads", "-1"});
  EXPECT_EQ(run.code, 2);
  EXPECT_NE(run.err.find("--threads"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(Path("camera.csv")));
}

TEST_F(DetectTest, IntrinsicsFromParallelBoardsAreRefused) {
  // Three views of a board parallel to the image plane: Zhang's method cannot separate focal
  // length from distance (calibrateCamera still returns an f, with a small σ).
  const std::string images = Images({"parallel_0.png", "parallel_1.png", "parallel_2.png"});
  cli_test::Outcome run = Hecal(
      {"detect", "--images", images, "--target", TargetFile(), "--output", Path("camera.csv")});
  EXPECT_EQ(run.code, 2);
  EXPECT_NE(run.err.find("--intrinsics"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("nearly parallel"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(Path("camera.csv")));
  EXPECT_FALSE(std::filesystem::exists(Path("camera.camera.yaml")));

  // With the intrinsics given, the same images give poses (a fronto-parallel pose is fine).
  run = Hecal({"detect", "--images", images, "--target", TargetFile(), "--intrinsics",
               Write("camera.yaml", CameraYaml(TrueCamera())), "--output", Path("camera.csv")});
  ASSERT_EQ(run.code, 0) << run.err;
  const csv_test::Csv poses = csv_test::ReadCsv(Path("camera.csv"));
  const std::vector<Pose> truth = ParallelViews();
  ASSERT_EQ(poses.rows.size(), truth.size());
  for (std::size_t i = 0; i < truth.size(); ++i) {
    EXPECT_LT(TranslationErrorMm(RowPose(poses, i), truth[i]), 1.0) << i;
  }
}

#else

TEST_F(CliTest, DetectNeedsTheVisionLayer) {
  const cli_test::Outcome run = Hecal({"detect", "--images", Path("."), "--target", Path("t.yaml"),
                                       "--output", Path("camera.csv")});
  EXPECT_EQ(run.code, 2);
  EXPECT_NE(run.err.find("HECAL_BUILD_VISION=ON"), std::string::npos) << run.err;
}

#endif

}  // namespace
}  // namespace hecal::cli
