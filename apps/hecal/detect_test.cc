// `hecal detect` end to end on synthetic images rendered (vision/render.h) with a known camera at
// known poses: the poses in camera.csv against the truth with given intrinsics (also from one
// image, from one sub-folder per station, and of a single AprilTag), the estimated intrinsics
// (camera.yaml) against the true camera without them, the points file against the projected
// corners, the report; intrinsics that do not fit the images (wrong fx, cx/cy swapped, another
// resolution); and bad input (exit 2, the file named, nothing written).
// Output files are read with the tests' own small CSV reader, quaternions turned into rotations
// with Eigen, independently of hecal's pose-table reader.
#include "detect.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli_test_util.h"

#if defined(HECAL_HAVE_OPENCV_PEERS)
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <numbers>
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "hecal/pose/camera_model.h"
#include "hecal/pose/target.h"
#include "hecal/vision/render.h"
#include "testing/camera_yaml.h"
#include "testing/csv_reader.h"
#include "testing/detection_errors.h"
#include "testing/render_once.h"
#include "testing/rendered_scene.h"
#endif

namespace hecal::cli {
namespace {

using cli_test::CliTest;
using cli_test::Hecal;

#if defined(HECAL_HAVE_OPENCV_PEERS)

using hecal::testing::Board;
using hecal::testing::CameraYaml;
using hecal::testing::kBoardYaml;
using hecal::testing::kTagYaml;
using hecal::testing::MakeRenderedScene;
using hecal::testing::RenderCamera;
using hecal::testing::RotationErrorDeg;
using hecal::testing::SpreadViews;
using hecal::testing::Tag;
using hecal::testing::TagSpread;
using hecal::testing::TranslationErrorMm;
using hecal::testing::ViewFileName;

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
class DetectTest : public hecal::testing::RenderOnce<DetectTest, CliTest> {
 public:
  static constexpr const char* kRenderFolder = "detect_test_renders";
  static void Render(const std::filesystem::path& dir) {
    MakeRenderedScene({.first_seed = 2, .folder = dir});
    MakeRenderedScene(
        {.views = ParallelViews(), .first_seed = 8, .folder = dir, .name = "parallel"});
    MakeRenderedScene({.target = Tag(),
                       .views = SpreadViews(TagSpread(3)),
                       .first_seed = 11,
                       .folder = dir,
                       .name = "tag"});
  }

 protected:
  static std::string ViewName(std::size_t i) { return ViewFileName("view", i); }
  static std::string TagName(std::size_t i) { return ViewFileName("tag", i); }

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

  std::string TargetFile() { return Write("target.yaml", kBoardYaml); }
  std::string CameraFile(const pose::CameraModel& camera = RenderCamera()) {
    return Write("camera.yaml", CameraYaml(camera));
  }
  // `hecal detect` on `images` with the board and the given intrinsics (a camera file without
  // width and height when the camera has none).
  cli_test::Outcome DetectWith(const std::string& images, const pose::CameraModel& camera) {
    std::string yaml = CameraYaml(camera);
    if (camera.width == 0) {
      for (const std::string key : {"\nwidth: 0", "\nheight: 0"}) {
        yaml.erase(yaml.find(key), key.size());
      }
    }
    return Hecal({"detect", "--images", images, "--target", TargetFile(), "--intrinsics",
                  Write("camera.yaml", yaml), "--output", Path("camera.csv")});
  }
};

Pose RowPose(const csv_test::Csv& csv, std::size_t row) {
  const Eigen::Quaterniond q(csv.Number(row, "qw"), csv.Number(row, "qx"), csv.Number(row, "qy"),
                             csv.Number(row, "qz"));
  return MakePose(
      q.normalized().toRotationMatrix(),
      Eigen::Vector3d(csv.Number(row, "x"), csv.Number(row, "y"), csv.Number(row, "z")));
}

TEST_F(DetectTest, PosesWithGivenIntrinsicsMatchTheRenderedTruth) {
  const pose::CameraModel camera = RenderCamera();
  const std::vector<Pose> all = SpreadViews();
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

// --report: the detect page (docs/report.md, "The detect page"), written with the other outputs:
// every used image with its corners, residuals, pose and thumbnail.
TEST_F(DetectTest, ReportIsTheDetectPage) {
  const std::string images = FirstViews(3);
  const cli_test::Outcome run =
      Hecal({"detect", "--images", images, "--target", TargetFile(), "--intrinsics", CameraFile(),
             "--output", Path("camera.csv"), "--report", Path("detect.html")});
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_NE(run.out.find("the page to " + Path("detect.html")), std::string::npos) << run.out;
  const std::string page = Read("detect.html");
  const size_t begin = page.find("<script type=\"application/json\" id=\"hecal-data\">");
  ASSERT_NE(begin, std::string::npos);
  const size_t start = page.find('>', begin) + 1;
  const nlohmann::json data =
      nlohmann::json::parse(page.substr(start, page.find("</script>", start) - start));
  EXPECT_EQ(data["kind"], "detect");
  ASSERT_EQ(data["per_image"].size(), 3u);
  const nlohmann::json& image = data["per_image"][1];
  EXPECT_EQ(image["id"], "view_01");
  EXPECT_EQ(image["file"], "view_01.png");
  EXPECT_EQ(image["points_px"].size(), 54u);
  EXPECT_EQ(image["residuals_px"].size(), 54u);
  EXPECT_LT(image["rms_px"].get<double>(), 0.2);
  EXPECT_EQ(data["thumbnails"]["count"], 3);
  EXPECT_EQ(
      data["thumbnails"]["by_id"]["view_02"].get<std::string>().rfind("data:image/jpeg;base64,", 0),
      0u);
  // The page is one of the outputs checked before detection: it may not overwrite an input.
  const cli_test::Outcome clash =
      Hecal({"detect", "--images", images, "--target", TargetFile(), "--intrinsics", CameraFile(),
             "--output", Path("other.csv"), "--report", TargetFile()});
  EXPECT_EQ(clash.code, 2);
  EXPECT_NE(clash.err.find("--report"), std::string::npos) << clash.err;
  EXPECT_FALSE(std::filesystem::exists(Path("other.csv")));
}

TEST_F(DetectTest, EstimatesTheIntrinsicsWhenNotGiven) {
  const pose::CameraModel camera = RenderCamera();
  const std::vector<Pose> truth = SpreadViews();
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
  const pose::CameraModel camera = RenderCamera();
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
  EXPECT_NE(run.err.find("cannot decode the image: it is not a PNG"), std::string::npos) << run.err;

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
  pose::CameraModel other = RenderCamera();
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
  const std::string images = Images({"parallel_00.png", "parallel_01.png", "parallel_02.png"});
  cli_test::Outcome run = Hecal(
      {"detect", "--images", images, "--target", TargetFile(), "--output", Path("camera.csv")});
  EXPECT_EQ(run.code, 2);
  EXPECT_NE(run.err.find("--intrinsics"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("nearly parallel"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(Path("camera.csv")));
  EXPECT_FALSE(std::filesystem::exists(Path("camera.camera.yaml")));

  // With the intrinsics given, the same images give poses (a fronto-parallel pose is fine).
  run = Hecal({"detect", "--images", images, "--target", TargetFile(), "--intrinsics",
               Write("camera.yaml", CameraYaml(RenderCamera())), "--output", Path("camera.csv")});
  ASSERT_EQ(run.code, 0) << run.err;
  const csv_test::Csv poses = csv_test::ReadCsv(Path("camera.csv"));
  const std::vector<Pose> truth = ParallelViews();
  ASSERT_EQ(poses.rows.size(), truth.size());
  for (std::size_t i = 0; i < truth.size(); ++i) {
    EXPECT_LT(TranslationErrorMm(RowPose(poses, i), truth[i]), 1.0) << i;
  }
}

// With the intrinsics given, one image is enough for its pose; without them, 3 are needed for the
// intrinsics, and the message says so and how to do with fewer.
TEST_F(DetectTest, OneImageIsEnoughWithIntrinsics) {
  const std::string images = FirstViews(1);
  cli_test::Outcome run = DetectWith(images, RenderCamera());
  ASSERT_EQ(run.code, 0) << run.err;
  const csv_test::Csv poses = csv_test::ReadCsv(Path("camera.csv"));
  ASSERT_EQ(poses.rows.size(), 1u);
  EXPECT_LT(RotationErrorDeg(RowPose(poses, 0), SpreadViews()[0]), 0.05);
  EXPECT_LT(TranslationErrorMm(RowPose(poses, 0), SpreadViews()[0]), 0.1);
  std::filesystem::remove(Path("camera.csv"));

  run = Hecal(
      {"detect", "--images", images, "--target", TargetFile(), "--output", Path("camera.csv")});
  EXPECT_EQ(run.code, 2);
  EXPECT_NE(run.err.find("only 1 of the 1 image(s)"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("estimating the intrinsics needs at least 3 views (with --intrinsics "
                         "camera.yaml one view is enough)"),
            std::string::npos)
      << run.err;
  EXPECT_FALSE(std::filesystem::exists(Path("camera.csv")));
}

// One sub-folder per station (pose_NN/image.png beside a pose file): the station id is the
// sub-folder's name, in camera.csv, the points file and the report. With images at the top level
// too, those win, with a note.
TEST_F(DetectTest, StationsInSubFolders) {
  for (std::size_t i = 0; i < 3; ++i) {
    const std::filesystem::path station = dir_ / "captures" / ("pose_0" + std::to_string(i));
    std::filesystem::create_directories(station);
    std::filesystem::copy_file(RenderDir() / ViewName(i), station / "image.png");
    Write("captures/pose_0" + std::to_string(i) + "/pose.yaml", "robot pose: not read\n");
  }
  cli_test::Outcome run = DetectWith(Path("captures"), RenderCamera());
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_NE(run.out.find("3 station sub-folder(s) in"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("pose_01/image.png"), std::string::npos) << run.out;
  const csv_test::Csv poses = csv_test::ReadCsv(Path("camera.csv"));
  ASSERT_EQ(poses.rows.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(poses.Text(i, "id"), "pose_0" + std::to_string(i));
    EXPECT_LT(RotationErrorDeg(RowPose(poses, i), SpreadViews()[i]), 0.05) << i;
  }
  EXPECT_EQ(csv_test::ReadCsv(Path("camera.points.csv")).Text(54, "id"), "pose_01");

  std::filesystem::copy_file(RenderDir() / ViewName(3), dir_ / "captures" / "loose.png");
  run = DetectWith(Path("captures"), RenderCamera());
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_NE(run.err.find("hecal: note: " + Path("captures") +
                         " holds 1 image(s) and 3 "
                         "sub-folder(s): using the images"),
            std::string::npos)
      << run.err;
  EXPECT_EQ(csv_test::ReadCsv(Path("camera.csv")).Text(0, "id"), "loose");

  // A station sub-folder with two images is an error naming it.
  std::filesystem::remove(dir_ / "captures" / "loose.png");
  std::filesystem::copy_file(RenderDir() / ViewName(4), dir_ / "captures" / "pose_02" / "b.png");
  std::filesystem::remove(Path("camera.csv"));
  run = DetectWith(Path("captures"), RenderCamera());
  EXPECT_EQ(run.code, 2);
  EXPECT_NE(run.err.find(Path("captures/pose_02") + ": this station's sub-folder holds 2 images"),
            std::string::npos)
      << run.err;
  EXPECT_FALSE(std::filesystem::exists(Path("camera.csv")));
}

// A single AprilTag (tag36h11 id 3, 100 mm): its centre is the target origin, so the poses are
// the rendered ones; 4 points per image. Its intrinsics cannot come from the images.
TEST_F(DetectTest, SingleTagPoses) {
  const std::string images = Images({TagName(0), TagName(1), TagName(2)});
  const std::string target = Write("tag.yaml", kTagYaml);
  cli_test::Outcome run = Hecal({"detect", "--images", images, "--target", target, "--intrinsics",
                                 CameraFile(), "--output", Path("camera.csv")});
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_NE(run.out.find("target apriltag tag36h11 id 3 (4 points)"), std::string::npos) << run.out;
  const csv_test::Csv poses = csv_test::ReadCsv(Path("camera.csv"));
  const std::vector<Pose> truth = SpreadViews(TagSpread(3));
  ASSERT_EQ(poses.rows.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    // Measured 0.02–0.07° and 0.56–0.76 mm: the corners sit ~0.27 px outward, where the lens
    // bends the straight edges they are fitted to (calibrate_images_test, SingleTagStations).
    const Pose T = RowPose(poses, i);
    std::printf("tag view %zu: %.4f deg, %.3f mm\n", i, RotationErrorDeg(T, truth[i]),
                TranslationErrorMm(T, truth[i]));
    EXPECT_LT(RotationErrorDeg(T, truth[i]), 0.2) << i;
    EXPECT_LT(TranslationErrorMm(T, truth[i]), 1.0) << i;
  }
  EXPECT_EQ(csv_test::ReadCsv(Path("camera.points.csv")).rows.size(), 12u);
  std::filesystem::remove(Path("camera.csv"));

  run = Hecal({"detect", "--images", images, "--target", target, "--output", Path("camera.csv")});
  EXPECT_EQ(run.code, 2);
  EXPECT_NE(run.err.find("--intrinsics"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("4 points per image"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(Path("camera.csv")));
}

// Given intrinsics that do not fit the images (vision/intrinsics_fit.h): fx 10× too large, or
// those of twice the resolution, are refused with the likely mistake named and nothing written;
// cx and cy swapped (1.8 px RMS on these 640 × 480 views, under the 2 px limit) is a warning that
// names it, and the poses are written.
TEST_F(DetectTest, IntrinsicsThatDoNotFitTheImagesAreCaught) {
  const std::string images = FirstViews(4);
  pose::CameraModel focal = RenderCamera();
  focal.fx *= 10.0;
  focal.fy *= 10.0;
  focal.width = focal.height = 0;
  cli_test::Outcome run = DetectWith(images, focal);
  EXPECT_EQ(run.code, 2);
  EXPECT_NE(run.err.find(Path("camera.yaml") + ": the intrinsics do not fit the images"),
            std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("fx, fy look 10.0"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("times too large"), std::string::npos) << run.err;
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  EXPECT_FALSE(std::filesystem::exists(Path("camera.csv")));
  EXPECT_FALSE(std::filesystem::exists(Path("camera.points.csv")));

  pose::CameraModel doubled = RenderCamera();  // the intrinsics of 1280 × 960 images, no size
  doubled.fx *= 2.0;
  doubled.fy *= 2.0;
  doubled.cx = 2.0 * doubled.cx + 0.5;
  doubled.cy = 2.0 * doubled.cy + 0.5;
  doubled.width = doubled.height = 0;
  run = DetectWith(images, doubled);
  EXPECT_EQ(run.code, 2);
  EXPECT_NE(run.err.find("intrinsics of images 2.0"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("(about 1280x960)"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(Path("camera.csv")));

  pose::CameraModel swapped = RenderCamera();
  std::swap(swapped.cx, swapped.cy);
  run = DetectWith(images, swapped);
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_NE(run.err.find("hecal: warning: " + Path("camera.yaml") +
                         ": the intrinsics fit the images poorly"),
            std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("cx and cy look swapped"), std::string::npos) << run.err;
  EXPECT_TRUE(std::filesystem::exists(Path("camera.csv")));
}

// The camera file's width × height against the images': a resize is recognised and the scaled
// intrinsics given; a quarter turn is named.
TEST_F(DetectTest, CameraSizeAgainstImageSize) {
  const std::string images = FirstViews(1);
  pose::CameraModel large = RenderCamera();
  large.fx *= 2.0;
  large.fy *= 2.0;
  large.width = 1280;
  large.height = 960;
  cli_test::Outcome run = DetectWith(images, large);
  EXPECT_EQ(run.code, 2);
  EXPECT_NE(run.err.find("the intrinsics are for 1280x960 images but the images are 640x480"),
            std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("resized by 0.5000"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("fx 620.000, fy 622.000"), std::string::npos) << run.err;

  pose::CameraModel turned = RenderCamera();
  turned.width = 480;
  turned.height = 640;
  run = DetectWith(images, turned);
  EXPECT_EQ(run.code, 2);
  EXPECT_NE(run.err.find("turned a quarter turn"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(Path("camera.csv")));
}

#else

using DetectWithoutVision = CliTest;

TEST_F(DetectWithoutVision, DetectNeedsTheVisionLayer) {
  const cli_test::Outcome run = Hecal({"detect", "--images", Path("."), "--target", Path("t.yaml"),
                                       "--output", Path("camera.csv")});
  EXPECT_EQ(run.code, 2);
  EXPECT_NE(run.err.find("HECAL_BUILD_VISION=ON"), std::string::npos) << run.err;
}

#endif

}  // namespace
}  // namespace hecal::cli
