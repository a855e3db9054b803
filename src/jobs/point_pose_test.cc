#include "hecal/jobs/point_pose.h"

#include <gtest/gtest.h>

#include <functional>
#include <iomanip>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "hecal/core/error.h"
#include "testing/pose_scenes.h"
#include "testing/scratch_folder.h"

namespace hecal::jobs {
namespace {

void ExpectInvalid(const std::function<void(PointPoseOptions&)>& spoil, const std::string& field,
                   const std::string& problem) {
  PointPoseOptions options;
  options.focal = 1000.0;
  spoil(options);
  std::string why;
  EXPECT_FALSE(options.IsValid(&why)) << field;
  EXPECT_EQ(why.rfind("PointPoseOptions." + field + ": ", 0), 0u) << why;
  EXPECT_NE(why.find(problem), std::string::npos) << why;
  EXPECT_THROW(EstimatePoseFromFiles(options), InputError);  // before any file is read
}

TEST(PointPoseOptions, ValidWithOneCamera) {
  PointPoseOptions options;
  std::string why;
  options.focal = 800.0;
  EXPECT_TRUE(options.IsValid(&why)) << why;
  options.focal.reset();
  options.intrinsics = "camera.yaml";
  EXPECT_TRUE(options.IsValid(&why)) << why;
}

TEST(PointPoseOptions, EachCheckedFieldRejectsABadValue) {
  ExpectInvalid([](PointPoseOptions& o) { o.focal.reset(); }, "focal", "exactly one");
  ExpectInvalid([](PointPoseOptions& o) { o.intrinsics = "camera.yaml"; }, "focal", "exactly one");
  ExpectInvalid([](PointPoseOptions& o) { o.focal = -3.0; }, "focal",
                "expected a positive number, got '-3'");
  ExpectInvalid([](PointPoseOptions& o) { o.focal = std::numeric_limits<double>::infinity(); },
                "focal", "positive");
  ExpectInvalid(
      [](PointPoseOptions& o) {
        o.focal.reset();
        o.intrinsics = "camera.yaml";
        o.principal_point = Eigen::Vector2d(1, 2);
      },
      "principal_point", "comes from the camera file");
  ExpectInvalid(
      [](PointPoseOptions& o) {
        o.principal_point = Eigen::Vector2d(std::numeric_limits<double>::quiet_NaN(), 0);
      },
      "principal_point", "finite");
  ExpectInvalid([](PointPoseOptions& o) { o.pixel_sigma = 0.0; }, "pixel_sigma",
                "above 0 to 100 px");
  ExpectInvalid([](PointPoseOptions& o) { o.pixel_sigma = 101.0; }, "pixel_sigma", "got 101");
}

class PointPoseFiles : public testing::ScratchFolderTest {
 protected:
  PointPoseFiles() : ScratchFolderTest("hecal_point_pose") {}
};

// Exact pixels of a distortion-free pinhole, object points in mm with ids, the image points a
// shuffled subset: DLT returns the true pose, the pairs follow the image file.
TEST_F(PointPoseFiles, PairsByIdAndRecoversTheTruePose) {
  pose::CameraModel camera = pose::CameraModel::Pinhole(1100.0);
  camera.cx = 600.0;
  camera.cy = 450.0;
  std::mt19937_64 rng(3);
  const testing::PointView scene =
      testing::RandomScene(rng, 12, testing::PointShape::kVolume, camera);
  std::ostringstream object, image;
  object << std::setprecision(17) << "id,x_mm,y_mm,z_mm\n";
  for (std::size_t k = 0; k < scene.object_points.size(); ++k) {
    const Eigen::Vector3d P = 1000.0 * scene.object_points[k];
    object << 'p' << k << ',' << P.x() << ',' << P.y() << ',' << P.z() << '\n';
  }
  const std::vector<std::size_t> order = {7, 0, 3, 11, 5, 9, 1, 4, 10, 2};
  image << std::setprecision(17) << "id,u,v\n";
  for (std::size_t k : order) {
    image << 'p' << k << ',' << scene.pixels[k].x() << ',' << scene.pixels[k].y() << '\n';
  }
  PointPoseOptions options;
  options.points = Write("object.csv", object.str());
  options.image_points = Write("image.csv", image.str());
  options.focal = 1100.0;
  options.principal_point = Eigen::Vector2d(600.0, 450.0);
  options.method = pose::PoseMethod::kDlt;
  const PointPoseResult result = EstimatePoseFromFiles(options);
  EXPECT_EQ(result.points, order.size());
  EXPECT_EQ(result.unit, io::LengthUnit::kMillimetre);
  ASSERT_EQ(result.point_ids.size(), order.size());
  EXPECT_EQ(result.point_ids[0], std::optional<std::string>("p7"));
  EXPECT_TRUE(result.estimate.T_camera_target.isApprox(scene.T_camera_target, 1e-8));
  EXPECT_LT(result.estimate.rms_px, 1e-6);

  // A solver given in the options replaces the method and sees the paired points in metres.
  std::size_t seen = 0;
  options.solver = [&](const std::vector<Eigen::Vector3d>& points,
                       const std::vector<Eigen::Vector2d>& pixels, const pose::CameraModel& c,
                       const pose::PoseOptions&) {
    seen = pixels.size();
    EXPECT_TRUE(points[0].isApprox(scene.object_points[7], 1e-12));
    EXPECT_EQ(c.cx, 600.0);
    pose::PoseEstimate estimate;
    estimate.method = "peer";
    return estimate;
  };
  EXPECT_EQ(EstimatePoseFromFiles(options).estimate.method, "peer");
  EXPECT_EQ(seen, order.size());
}

TEST_F(PointPoseFiles, AnImageIdThatIsNoObjectPointNamesItsLine) {
  PointPoseOptions options;
  options.points = Write("object.csv", "id,x,y,z\na,0,0,1\nb,1,0,1\n");
  options.image_points = Write("image.csv", "id,u,v\na,0,0\nc,1,1\n");
  options.focal = 800.0;
  try {
    EstimatePoseFromFiles(options);
    ADD_FAILURE() << "accepted an unknown id";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), options.image_points);
    EXPECT_EQ(e.line(), 3);
  }
}

}  // namespace
}  // namespace hecal::jobs
