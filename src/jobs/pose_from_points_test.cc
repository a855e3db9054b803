// Every pose method on written point files with a known pose: exact pixels of a distortion-free
// pinhole, so each method returns the true T_camera_target (ippe on a plane, the others on points
// in a volume); the covariance exactly for the refined methods; the list of methods and their
// names (an unknown name has no method); the point options checked before any file is read.
#include "hecal/jobs/pose_from_points.h"

#include <gtest/gtest.h>

#include <iomanip>
#include <optional>
#include <random>
#include <set>
#include <sstream>
#include <string>

#include "hecal/core/error.h"
#include "testing/pose_scenes.h"
#include "testing/scratch_folder.h"

namespace hecal::jobs {
namespace {

class PoseFromPoints : public testing::ScratchFolderTest {
 protected:
  PoseFromPoints() : ScratchFolderTest("hecal_pose_from_points") {}

  // Options for `scene` written as object.csv (metres, ids) and image.csv (pixels, ids).
  PoseFromFilesOptions Files(const testing::PointView& scene) const {
    std::ostringstream object, image;
    object << std::setprecision(17) << "id,x,y,z\n";
    image << std::setprecision(17) << "id,u,v\n";
    for (std::size_t k = 0; k < scene.object_points.size(); ++k) {
      const Eigen::Vector3d& P = scene.object_points[k];
      object << 'p' << k << ',' << P.x() << ',' << P.y() << ',' << P.z() << '\n';
      image << 'p' << k << ',' << scene.pixels[k].x() << ',' << scene.pixels[k].y() << '\n';
    }
    PoseFromFilesOptions options;
    options.points.points = Write("object.csv", object.str());
    options.points.image_points = Write("image.csv", image.str());
    options.points.focal = scene.camera.fx;
    options.points.principal_point = Eigen::Vector2d(scene.camera.cx, scene.camera.cy);
    options.points.pixel_sigma = 0.5;
    return options;
  }
};

pose::CameraModel Pinhole() {
  pose::CameraModel camera = pose::CameraModel::Pinhole(1000.0);
  camera.cx = 640.0;
  camera.cy = 480.0;
  return camera;
}

TEST(PoseMethods, ListsThePoseLayersMethodsThenOpenCvs) {
  std::vector<std::string> names;
  for (const PoseMethodEntry& entry : PoseMethods()) {
    names.emplace_back(entry.name);
    EXPECT_FALSE(entry.help.empty()) << entry.name;
    EXPECT_EQ(ParsePoseMethod(entry.name), std::optional<AnyPoseMethod>(entry.method));
  }
  EXPECT_EQ(names, (std::vector<std::string>{"linear", "linear-raw", "dlt", "ippe", "sqpnp", "epnp",
                                             "iterative"}));
  EXPECT_EQ(PoseMethods()[1].method, AnyPoseMethod(pose::PoseMethod::kLinearRaw));
  EXPECT_EQ(PoseMethods()[4].method, AnyPoseMethod(vision::PnpMethod::kSqpnp));
  EXPECT_EQ(PoseMethodNames(), "linear, linear-raw, dlt, ippe, sqpnp, epnp, iterative");
  EXPECT_FALSE(ParsePoseMethod("p3p"));
  EXPECT_FALSE(ParsePoseMethod("IPPE"));
  EXPECT_FALSE(ParsePoseMethod(" dlt"));
}

TEST_F(PoseFromPoints, EveryMethodRecoversTheTruePose) {
  // Followed by the reprojection refinement, hence with a covariance (pose_method.h,
  // opencv_pnp.h: OpenCV's closed forms are not refined).
  const std::set<std::string> refined = {"linear", "dlt", "iterative"};
  for (const PoseMethodEntry& entry : PoseMethods()) {
    const std::string name(entry.name);
    std::mt19937_64 rng(11);
    const testing::PointView scene = testing::RandomScene(
        rng, 20, name == "ippe" ? testing::PointShape::kPlane : testing::PointShape::kVolume,
        Pinhole());
    PoseFromFilesOptions options = Files(scene);
    options.method = entry.method;
    const jobs::PointPoseResult result = EstimatePoseFromFiles(options);
    EXPECT_EQ(result.estimate.method, name);
    EXPECT_EQ(result.points, 20u);
    const Pose& T = result.estimate.T_camera_target;
    EXPECT_LT((T.translation() - scene.T_camera_target.translation()).norm(), 1e-6) << name;
    EXPECT_TRUE(T.linear().isApprox(scene.T_camera_target.linear(), 1e-6)) << name;
    EXPECT_LT(result.estimate.rms_px, 1e-4) << name;
    EXPECT_EQ(result.estimate.covariance.has_value(), refined.count(name) == 1) << name;
  }
}

TEST_F(PoseFromPoints, TheMethodReplacesWhatThePointOptionsHeld) {
  std::mt19937_64 rng(5);
  PoseFromFilesOptions options =
      Files(testing::RandomScene(rng, 12, testing::PointShape::kVolume, Pinhole()));
  options.points.method = pose::PoseMethod::kLinearRaw;
  options.points.solver = [](const std::vector<Eigen::Vector3d>&,
                             const std::vector<Eigen::Vector2d>&, const pose::CameraModel&,
                             const pose::PoseOptions&) -> pose::PoseEstimate {
    throw std::logic_error("not the method asked for");
  };
  options.method = pose::PoseMethod::kDlt;
  EXPECT_EQ(EstimatePoseFromFiles(options).estimate.method, "dlt");
}

TEST_F(PoseFromPoints, ThePointOptionsAreCheckedBeforeAnyFileIsRead) {
  PoseFromFilesOptions options;
  options.points.points = "missing-object.csv";
  options.points.image_points = "missing-image.csv";
  options.points.focal = -1.0;
  options.method = vision::PnpMethod::kEpnp;
  std::string why;
  EXPECT_FALSE(options.IsValid(&why));
  EXPECT_EQ(why.rfind("PointPoseOptions.focal: expected a positive number", 0), 0u) << why;
  try {
    EstimatePoseFromFiles(options);
    ADD_FAILURE() << "accepted a negative focal length";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "PointPoseOptions.focal");
  }
}

}  // namespace
}  // namespace hecal::jobs
