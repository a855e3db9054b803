// OpenCV 4.6 as a peer on identical data: Project and its Jacobian against cv::projectPoints
// (rvec = tvec = 0, so ∂(u, v)/∂tvec is ∂(u, v)/∂point), Undistort against cv::undistortPoints.
#include <gtest/gtest.h>

#include <opencv2/calib3d.hpp>
#include <random>
#include <vector>

#include "hecal/core/random_draws.h"
#include "hecal/pose/camera_model.h"

namespace hecal::pose {
namespace {

CameraModel PeerCamera(const std::array<double, 5>& distortion) {
  CameraModel camera;
  camera.fx = 1050.0;
  camera.fy = 1040.0;
  camera.cx = 955.5;
  camera.cy = 541.0;
  camera.width = 1920;
  camera.height = 1080;
  camera.distortion = distortion;
  return camera;
}

cv::Matx33d CameraMatrix(const CameraModel& camera) {
  return {camera.fx, 0.0, camera.cx, 0.0, camera.fy, camera.cy, 0.0, 0.0, 1.0};
}

std::vector<Eigen::Vector3d> RandomPoints(std::mt19937_64& rng, int count) {
  hecal::UniformRealDistribution lateral(-0.8, 0.8), depth(0.2, 5.0);
  std::vector<Eigen::Vector3d> points;
  for (int k = 0; k < count; ++k) {
    const double z = depth(rng);
    const double y = lateral(rng) * z;  // y before x: the order the tests' data were generated in
    const double x = lateral(rng) * z;
    points.emplace_back(x, y, z);
  }
  return points;
}

TEST(CameraModelOpenCv, ProjectAndJacobianMatchProjectPoints) {
  std::mt19937_64 rng(21);
  for (const auto& distortion : {std::array<double, 5>{0.0, 0.0, 0.0, 0.0, 0.0},
                                 std::array<double, 5>{-0.12, 0.08, 1e-3, -2e-3, -0.01},
                                 std::array<double, 5>{-0.38, 0.15, 3e-3, 2e-3, -0.02}}) {
    const CameraModel camera = PeerCamera(distortion);
    const std::vector<Eigen::Vector3d> points = RandomPoints(rng, 300);
    std::vector<cv::Point3d> object;
    for (const Eigen::Vector3d& X : points) object.emplace_back(X.x(), X.y(), X.z());
    std::vector<cv::Point2d> image;
    cv::Mat jacobian;
    cv::projectPoints(object, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), CameraMatrix(camera),
                      cv::Vec<double, 5>(distortion.data()), image, jacobian);
    ASSERT_EQ(jacobian.cols, 15);  // rvec 3, tvec 3, f 2, c 2, distortion 5
    for (std::size_t k = 0; k < points.size(); ++k) {
      Eigen::Matrix<double, 2, 3> J;
      const Eigen::Vector2d uv = Project(camera, points[k], &J);
      EXPECT_NEAR(uv.x(), image[k].x, 1e-9);
      EXPECT_NEAR(uv.y(), image[k].y, 1e-9);
      for (int r = 0; r < 2; ++r) {
        for (int c = 0; c < 3; ++c) {
          const double peer = jacobian.at<double>(static_cast<int>(2 * k) + r, 3 + c);
          EXPECT_NEAR(J(r, c), peer, 1e-9 * (1.0 + std::abs(peer))) << k << " " << r << c;
        }
      }
    }
  }
}

TEST(CameraModelOpenCv, UndistortMatchesUndistortPoints) {
  // OpenCV iterates the fixed point x ← (x_d − tangential(x)) / radial(x), which converges for
  // moderate distortion; give it enough iterations to reach rounding.
  const CameraModel camera = PeerCamera({-0.12, 0.08, 1e-3, -2e-3, -0.01});
  std::vector<cv::Point2d> pixels;
  for (double u = 0.0; u < camera.width; u += 96.0) {
    for (double v = 0.0; v < camera.height; v += 90.0) pixels.emplace_back(u, v);
  }
  std::vector<cv::Point2d> peer;
  cv::undistortPoints(pixels, peer, CameraMatrix(camera),
                      cv::Vec<double, 5>(camera.distortion.data()), cv::noArray(), cv::noArray(),
                      cv::TermCriteria(cv::TermCriteria::COUNT, 200, 0.0));
  for (std::size_t k = 0; k < pixels.size(); ++k) {
    const std::optional<Eigen::Vector2d> p =
        Undistort(camera, Eigen::Vector2d(pixels[k].x, pixels[k].y));
    ASSERT_TRUE(p.has_value());
    EXPECT_NEAR(p->x(), peer[k].x, 1e-10) << pixels[k];
    EXPECT_NEAR(p->y(), peer[k].y, 1e-10) << pixels[k];
  }
}

}  // namespace
}  // namespace hecal::pose
