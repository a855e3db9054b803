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
#endif

namespace hecal::cli {
namespace {

using cli_test::CliTest;
using cli_test::Hecal;

#if defined(HECAL_HAVE_OPENCV_PEERS)

constexpr double kDeg = std::numbers::pi / 180.0;

// 9 × 6 inner corners (cols + rows odd: the square colours fix the order), 25 mm squares.
constexpr const char* kTargetYaml = "type: chessboard\ncols: 9\nrows: 6\nsquare: 0.025\n";

pose::TargetSpec Board() {
  pose::TargetSpec target;
  target.type = pose::TargetType::kChessboard;
  target.cols = 9;
  target.rows = 6;
  target.square = 0.025;
  return target;
}

pose::CameraModel TrueCamera() {
  pose::CameraModel camera;
  camera.fx = 620.0;
  camera.fy = 622.0;
  camera.cx = 321.5;
  camera.cy = 238.0;
  camera.width = 640;
  camera.height = 480;
  camera.distortion = {-0.12, 0.05, 0.0, 0.0, 0.0};
  return camera;
}

std::string CameraYaml(const pose::CameraModel& c) {
  std::ostringstream yaml;
  yaml << std::setprecision(17) << "fx: " << c.fx << "\nfy: " << c.fy << "\ncx: " << c.cx
       << "\ncy: " << c.cy << "\nwidth: " << c.width << "\nheight: " << c.height
       << "\ndistortion:\n  model: plumb_bob\n  coefficients: [" << c.distortion[0] << ", "
       << c.distortion[1] << ", " << c.distortion[2] << ", " << c.distortion[3] << ", "
       << c.distortion[4] << "]\n";
  return yaml.str();
}

// The camera `distance` from the board centre, tilted by `tilt` towards `azimuth` (x right,
// y down on the board), looking at the centre and then panned by (pan_x, pan_y) radians about
// its own x and y axes so the board lands in different parts of the image.
Pose ViewPose(double distance, double tilt, double azimuth, double pan_x, double pan_y) {
  const Eigen::Vector3d centre(0.1, 0.0625, 0.0);  // of the 8 × 5 squares between the corners
  const Eigen::Vector3d eye =
      centre + distance * Eigen::Vector3d(std::sin(tilt) * std::cos(azimuth),
                                          std::sin(tilt) * std::sin(azimuth), -std::cos(tilt));
  const Eigen::Vector3d z = (centre - eye).normalized();
  const Eigen::Vector3d x = Eigen::Vector3d::UnitY().cross(z).normalized();
  Eigen::Matrix3d R_target_camera;
  R_target_camera << x, z.cross(x), z;
  const Pose T_target_camera = MakePose(R_target_camera, eye);
  const Eigen::Matrix3d pan = (Eigen::AngleAxisd(pan_x, Eigen::Vector3d::UnitX()) *
                               Eigen::AngleAxisd(pan_y, Eigen::Vector3d::UnitY()))
                                  .toRotationMatrix();
  return MakePose(pan, Eigen::Vector3d::Zero()) * T_target_camera.inverse();
}

// Six views, tilted 15–35° in different directions, spread over the image.
std::vector<Pose> Views() {
  std::vector<Pose> views;
  for (int k = 0; k < 6; ++k) {
    views.push_back(ViewPose(0.38 + 0.02 * (k % 3), (15.0 + 10.0 * (k % 3)) * kDeg, k * 60.0 * kDeg,
                             (k % 2 == 0 ? 0.08 : -0.08), (k % 4 < 2 ? 0.12 : -0.12)));
  }
  return views;
}

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
    vision::RenderOptions options;
    options.blur_sigma = 0.6;
    options.noise_sigma = 1.0;
    options.supersampling = 4;
    const auto render = [&options](const std::string& name, const Pose& T_camera_target) {
      options.seed += 1;
      cv::imwrite((RenderDir() / name).string(),
                  vision::RenderTarget(Board(), TrueCamera(), T_camera_target, options));
    };
    const std::vector<Pose> views = Views();
    for (std::size_t i = 0; i < views.size(); ++i) render(ViewName(i), views[i]);
    const std::vector<Pose> parallel = ParallelViews();
    for (std::size_t i = 0; i < parallel.size(); ++i) {
      render("parallel_" + std::to_string(i) + ".png", parallel[i]);
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

// Rotation angle between two poses (deg) and translation distance (mm).
double RotationErrorDeg(const Pose& a, const Pose& b) {
  return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle() / kDeg;
}
double TranslationErrorMm(const Pose& a, const Pose& b) {
  return 1e3 * (a.translation() - b.translation()).norm();
}

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
