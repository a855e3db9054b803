// GlobalMatchesFromImages on rendered scenes with known camera motion: a chessboard seen from
// five views (testing/rendered_scene.h, robot poses of its hand–eye rig) for the target corners,
// and four stations of a textured plane (testing/textured_stations.h) for SIFT and ORB features.
// Asserted against the scenes' truth: matched rays lie on the true epipolar plane of their motion
// (residual ≪ 1 px at the focal length; ORB's coarser keypoints in the bulk), target corners on
// the true ray to the corner of their id; at most matches_per_motion per motion; the robot pose of
// every image, in order; the features' progress line; invalid options refused naming the field
// before any file is read.
#include "hecal/jobs/global_matches.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "hecal/core/error.h"
#include "hecal/pose/target.h"
#include "testing/camera_yaml.h"
#include "testing/pose_csv.h"
#include "testing/render_once.h"
#include "testing/rendered_scene.h"
#include "testing/textured_stations.h"
#include "testing/thrown.h"

namespace hecal::jobs {
namespace {

constexpr int kViews = 5;     // chessboard views
constexpr int kStations = 4;  // textured-plane stations
constexpr int kPerMotion = 30;

std::vector<Pose> BoardViews() {
  return testing::SpreadViews({.count = kViews});
}

// |v · (t̂ × R u)|: the sine of the angle between the first ray and the epipolar plane of the
// second, for the motion T_first_second (a point p2 in the second camera is R p2 + t in the first).
double EpipolarResidual(const global::BearingPair& pair, const Pose& T_first_second) {
  const Eigen::Vector3d normal =
      T_first_second.translation().normalized().cross(T_first_second.linear() * pair.second);
  return std::abs(pair.first.dot(normal));
}

class GlobalMatchesTest : public testing::RenderOnce<GlobalMatchesTest> {
 public:
  static constexpr const char* kRenderFolder = "global_matches_test";
  static void Render(const std::filesystem::path& dir) {
    testing::MakeRenderedScene({.views = BoardViews(), .first_seed = 7, .folder = dir / "board"});
    std::ofstream(dir / "target.yaml") << testing::kBoardYaml;
    std::ofstream(dir / "board.yaml") << testing::CameraYaml(testing::RenderCamera());
    std::vector<Pose> robot;
    for (const Pose& view : BoardViews()) robot.push_back(testing::RigRobotPose(view));
    std::ofstream(dir / "board_robot.csv") << testing::PoseCsv(robot);  // ids name no image
    testing::WriteStationFiles(Plane(), PlaneSpec().rendering, 3, dir / "plane");
  }

 protected:
  static testing::TexturedStationSpec PlaneSpec() {
    testing::TexturedStationSpec spec;
    spec.stations = kStations;
    spec.rendering.supersampling = 2;
    return spec;
  }
  static testing::TexturedStations Plane() { return testing::MakeTexturedStations(PlaneSpec(), 3); }

  static GlobalImageMatchOptions BoardOptions() {
    GlobalImageMatchOptions options;
    options.robot = (RenderDir() / "board_robot.csv").string();
    options.images = (RenderDir() / "board").string();
    options.target = (RenderDir() / "target.yaml").string();
    options.intrinsics = (RenderDir() / "board.yaml").string();
    options.matches_per_motion = kPerMotion;
    return options;
  }
  static GlobalImageMatchOptions PlaneOptions(MatchSource source) {
    GlobalImageMatchOptions options;
    options.robot = (RenderDir() / "plane" / "robot.csv").string();
    options.images = (RenderDir() / "plane" / "images").string();
    options.intrinsics = (RenderDir() / "plane" / "camera.yaml").string();
    options.source = source;
    options.matches_per_motion = kPerMotion;
    return options;
  }
};

void ExpectSamePoses(const std::vector<Pose>& actual, const std::vector<Pose>& expected) {
  ASSERT_EQ(actual.size(), expected.size());
  for (std::size_t i = 0; i < actual.size(); ++i) {
    EXPECT_TRUE(actual[i].isApprox(expected[i], 1e-12)) << "station " << i;
  }
}

// Corner j of a motion is the target's corner ids[j]: on the true ray to it in both views.
TEST_F(GlobalMatchesTest, TargetCornersLieOnTheTrueRays) {
  std::vector<std::string> progress, notes;
  const GlobalMatches matches = GlobalMatchesFromImages(
      BoardOptions(), {[&](const std::string& text) { progress.push_back(text); },
                       [&](const std::string& note) { notes.push_back(note); },
                       {}});
  const std::vector<Pose> views = BoardViews();
  std::vector<Pose> robot;
  for (const Pose& view : views) robot.push_back(testing::RigRobotPose(view));
  ExpectSamePoses(matches.T_base_gripper, robot);
  EXPECT_EQ(matches.focal, 0.5 * (620.0 + 622.0));
  EXPECT_FALSE(progress.empty());
  EXPECT_FALSE(notes.empty());  // the robot ids s0 … name no image: paired by order, noted

  const std::vector<pose::ObjectPoint> corners = pose::ObjectPoints(testing::Board());
  const double half_pixel = 0.5 / matches.focal;
  ASSERT_EQ(matches.motions.size(), std::size_t(kViews - 1));
  for (std::size_t k = 0; k < matches.motions.size(); ++k) {
    const GlobalMotion& motion = matches.motions[k];
    EXPECT_EQ(motion.first, int(k));
    EXPECT_EQ(motion.second, int(k + 1));
    EXPECT_EQ(motion.first_name, "view_0" + std::to_string(k));
    EXPECT_EQ(motion.pairs.size(), std::size_t(kPerMotion));  // 54 corners seen, 30 taken
    const Pose& first = views[k];
    const Pose& second = views[k + 1];
    for (const global::BearingPair& pair : motion.pairs) {
      const Eigen::Vector3d corner = corners[std::size_t(pair.id)].position;
      EXPECT_LT(std::acos(std::min(1.0, pair.first.dot((first * corner).normalized()))),
                half_pixel);
      EXPECT_LT(std::acos(std::min(1.0, pair.second.dot((second * corner).normalized()))),
                half_pixel);
      EXPECT_LT(EpipolarResidual(pair, first * second.inverse()), half_pixel);
    }
  }
}

// SIFT and ORB matches on the true epipolar planes (SIFT every one within 0.5 px, ORB the median
// within 0.5 px and 90 % within 1.5 px); the progress line gives the counts.
TEST_F(GlobalMatchesTest, FeatureMatchesFitTheTrueMotion) {
  const testing::TexturedStations plane = Plane();
  for (const MatchSource source : {MatchSource::kSift, MatchSource::kOrb}) {
    std::vector<std::string> progress;
    const GlobalMatches matches = GlobalMatchesFromImages(
        PlaneOptions(source), {[&](const std::string& text) { progress.push_back(text); }, {}, {}});
    ExpectSamePoses(matches.T_base_gripper, plane.T_base_gripper);
    EXPECT_EQ(matches.focal, 800.0);
    ASSERT_EQ(matches.motions.size(), std::size_t(kStations - 1));
    std::string line = "features: " + std::to_string(kStations) + " images, " +
                       std::to_string(kStations - 1) + " motions, " +
                       (source == MatchSource::kSift ? "SIFT" : "ORB") + " matches per motion:";
    std::vector<double> residuals;
    for (std::size_t k = 0; k < matches.motions.size(); ++k) {
      const GlobalMotion& motion = matches.motions[k];
      EXPECT_EQ(motion.first_name, "view_0" + std::to_string(k));
      EXPECT_GE(motion.pairs.size(), 8u);
      EXPECT_LE(motion.pairs.size(), std::size_t(kPerMotion));
      line += " " + std::to_string(motion.pairs.size());
      const Pose T_first_second = plane.T_base_camera[k].inverse() * plane.T_base_camera[k + 1];
      for (const global::BearingPair& pair : motion.pairs) {
        residuals.push_back(EpipolarResidual(pair, T_first_second) * matches.focal);  // pixels
      }
    }
    EXPECT_THAT(progress, ::testing::ElementsAre(line + "\n"));
    std::sort(residuals.begin(), residuals.end());
    // Measured: SIFT median 0.04 px, max 0.2 px; ORB (keypoints of coarse pyramid levels)
    // median 0.28 px, 90 % 0.93 px, max 3.6 px.
    if (source == MatchSource::kSift) {
      EXPECT_LT(residuals.back(), 0.5);
    } else {
      EXPECT_LT(residuals[residuals.size() / 2], 0.5);
      EXPECT_LT(residuals[residuals.size() * 9 / 10], 1.5);
    }
  }
}

// Refused naming the field, before any file is read (the paths below do not exist).
TEST(GlobalImageMatchOptions, InvalidOptionsNameTheField) {
  GlobalImageMatchOptions options;
  options.robot = "missing/robot.csv";
  options.images = "missing/images";
  options.target = "missing/target.yaml";
  options.intrinsics = "missing/camera.yaml";
  EXPECT_TRUE(options.IsValid(nullptr));
  const auto refused = [](const GlobalImageMatchOptions& bad, const std::string& field) {
    std::string why;
    EXPECT_FALSE(bad.IsValid(&why));
    EXPECT_EQ(why.rfind(field + ": ", 0), 0u) << why;
    const InputError error = testing::Thrown<InputError>([&] { GlobalMatchesFromImages(bad, {}); });
    EXPECT_EQ(error.source(), field) << error.what();
  };
  GlobalImageMatchOptions bad = options;
  bad.robot.clear();
  refused(bad, "GlobalImageMatchOptions.robot");
  bad = options;
  bad.images.clear();
  refused(bad, "GlobalImageMatchOptions.images");
  bad = options;
  bad.intrinsics.clear();
  refused(bad, "GlobalImageMatchOptions.intrinsics");
  bad = options;
  bad.target.clear();
  refused(bad, "GlobalImageMatchOptions.target");
  bad.source = MatchSource::kSift;  // features need no target
  EXPECT_TRUE(bad.IsValid(nullptr));
  bad = options;
  bad.threads = -1;
  refused(bad, "GlobalImageMatchOptions.threads");
  bad = options;
  bad.matches_per_motion = 0;
  refused(bad, "GlobalImageMatchOptions.matches_per_motion");
  bad = options;
  bad.pixel_sigma = std::nan("");
  refused(bad, "GlobalImageMatchOptions.pixel_sigma");
}

}  // namespace
}  // namespace hecal::jobs
