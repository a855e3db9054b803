// OpenCV 4.6 as a peer on identical noisy data: hecal's refined methods (linear, dlt) reach the
// maximum-likelihood pose that OpenCV's SOLVEPNP_ITERATIVE + solvePnPRefineLM reach.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <opencv2/calib3d.hpp>
#include <random>
#include <vector>

#include "hecal/pose/pose_method.h"
#include "testing/pose_scenes.h"

namespace hecal::pose {
namespace {

Pose OpenCvMaximumLikelihood(const std::vector<Eigen::Vector3d>& object_points,
                             const std::vector<Eigen::Vector2d>& pixels,
                             const CameraModel& camera) {
  std::vector<cv::Point3d> object;
  std::vector<cv::Point2d> image;
  for (std::size_t k = 0; k < object_points.size(); ++k) {
    object.emplace_back(object_points[k].x(), object_points[k].y(), object_points[k].z());
    image.emplace_back(pixels[k].x(), pixels[k].y());
  }
  const cv::Matx33d K(camera.fx, 0.0, camera.cx, 0.0, camera.fy, camera.cy, 0.0, 0.0, 1.0);
  const cv::Vec<double, 5> distortion(camera.distortion.data());
  cv::Mat rvec, tvec;
  EXPECT_TRUE(
      cv::solvePnP(object, image, K, distortion, rvec, tvec, false, cv::SOLVEPNP_ITERATIVE));
  cv::solvePnPRefineLM(
      object, image, K, distortion, rvec, tvec,
      cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 100, 1e-15));
  const Eigen::Vector3d w(rvec.at<double>(0), rvec.at<double>(1), rvec.at<double>(2));
  const Eigen::Matrix3d R = w.norm() > 0.0
                                ? Eigen::AngleAxisd(w.norm(), w.normalized()).toRotationMatrix()
                                : Eigen::Matrix3d::Identity();
  return MakePose(R, Eigen::Vector3d(tvec.at<double>(0), tvec.at<double>(1), tvec.at<double>(2)));
}

TEST(PoseMethodOpenCv, RefinedMethodsMatchOpenCvIterative) {
  std::mt19937_64 rng(1);
  for (testing::PointShape shape : {testing::PointShape::kVolume, testing::PointShape::kPlane}) {
    for (int trial = 0; trial < 20; ++trial) {
      const testing::PointView scene = testing::RandomScene(rng, 20, shape);
      const std::vector<Eigen::Vector2d> noisy = testing::AddPixelNoise(rng, scene.pixels, 1.0);
      const Pose peer = OpenCvMaximumLikelihood(scene.object_points, noisy, scene.camera);
      for (PoseMethod method : {PoseMethod::kLinear, PoseMethod::kDlt}) {
        if (method == PoseMethod::kLinear && shape == testing::PointShape::kPlane) continue;
        const Pose ours =
            EstimatePose(method, scene.object_points, noisy, scene.camera).T_camera_target;
        EXPECT_LT(Eigen::AngleAxisd(ours.linear().transpose() * peer.linear()).angle(), 1e-7)
            << Info(method).name;
        EXPECT_LT((ours.translation() - peer.translation()).norm(), 1e-7) << Info(method).name;
      }
    }
  }
}

}  // namespace
}  // namespace hecal::pose
