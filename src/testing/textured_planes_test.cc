// The textured-plane renderer (testing/textured_planes.h) against independent truth: sharp dots on
// a tilted plane, seen through a distorting lens, are imaged where pose::Project puts their
// centres (area centroids within 0.05 px); the nearest plane hides the ones behind it whatever
// their order in the list, and a plane behind the camera is not drawn; the blob texture is
// deterministic, spans black to white, and differs between seeds.
#include "testing/textured_planes.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "hecal/geometry/angle_units.h"

namespace hecal::testing {
namespace {

TEST(RenderPlanes, ImagesSharpDotsWhereTheCameraModelProjectsThem) {
  // 640 × 480, radial distortion of a machine-vision lens.
  const pose::CameraModel camera{
      620.0, 622.0, 321.5, 238.0, 640, 480, {-0.12, 0.05, 0.0, 0.0, 0.0}};
  const std::vector<Eigen::Vector2d> dots = {
      {0.0, 0.0}, {0.07, 0.05}, {-0.08, 0.06}, {0.09, -0.07}, {-0.06, -0.05}};
  constexpr double kRadius = 0.002;
  TexturedPlane plane;
  plane.T_world_plane =
      MakePose((Eigen::AngleAxisd(20 * kRadiansPerDegree, Eigen::Vector3d::UnitX()) *
                Eigen::AngleAxisd(-25 * kRadiansPerDegree, Eigen::Vector3d::UnitY()))
                   .toRotationMatrix(),
               Eigen::Vector3d(0.01, -0.02, 0.5));
  plane.width = 0.3;
  plane.height = 0.25;
  plane.texture = [&dots](double x, double y) {
    for (const Eigen::Vector2d& dot : dots) {
      if ((Eigen::Vector2d(x, y) - dot).norm() < kRadius) return 0.0;
    }
    return 1.0;
  };
  PlaneRenderOptions options;
  options.supersampling = 8;
  const Pose T_world_camera = Pose::Identity();
  const GreyImage image = RenderPlanes({plane}, camera, T_world_camera, options);
  ASSERT_EQ(image.width, 640);
  ASSERT_EQ(image.height, 480);
  for (const Eigen::Vector2d& dot : dots) {
    const Eigen::Vector2d truth =
        pose::Project(camera, plane.T_world_plane * Eigen::Vector3d(dot.x(), dot.y(), 0.0));
    // Area centroid of the darkness (white − grey) in a window around the truth; the paper
    // around a dot is exactly white, so only the dot weighs.
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    double total = 0.0;
    const int ci = static_cast<int>(std::lround(truth.x()));
    const int cj = static_cast<int>(std::lround(truth.y()));
    for (int j = cj - 10; j <= cj + 10; ++j) {
      for (int i = ci - 10; i <= ci + 10; ++i) {
        const double weight = options.white - image.At(i, j);
        sum += weight * Eigen::Vector2d(i, j);
        total += weight;
      }
    }
    ASSERT_GT(total, 0.0) << "no dot near " << truth.transpose();
    EXPECT_LT((sum / total - truth).norm(), 0.05)
        << "dot " << dot.transpose() << ": centroid " << (sum / total).transpose() << ", truth "
        << truth.transpose();
  }
}

TEST(RenderPlanes, TheNearestPlaneWinsWhateverTheOrder) {
  const pose::CameraModel camera{500.0, 500.0, 319.5, 239.5, 640, 480, {0.0, 0.0, 0.0, 0.0, 0.0}};
  const auto uniform = [](double r) { return [r](double, double) { return r; }; };
  const TexturedPlane back{MakePose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.0, 0.0, 0.6)),
                           0.4, 0.4, uniform(1.0)};
  const TexturedPlane front{
      MakePose(
          Eigen::AngleAxisd(30 * kRadiansPerDegree, Eigen::Vector3d::UnitY()).toRotationMatrix(),
          Eigen::Vector3d(0.0, 0.0, 0.4)),
      0.1, 0.1, uniform(0.0)};
  const TexturedPlane behind{MakePose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, 0, -0.3)),
                             10.0, 10.0, uniform(0.5)};
  const PlaneRenderOptions options;
  const GreyImage a = RenderPlanes({back, front, behind}, camera, Pose::Identity(), options);
  const GreyImage b = RenderPlanes({behind, front, back}, camera, Pose::Identity(), options);
  EXPECT_EQ(a.pixels, b.pixels);
  const auto pixel = [&](const GreyImage& image, const Eigen::Vector3d& p) {
    const Eigen::Vector2d uv = pose::Project(camera, p);
    return int(image.At(int(std::lround(uv.x())), int(std::lround(uv.y()))));
  };
  // The front plane's centre, in front of the back plane: black.
  EXPECT_EQ(pixel(a, Eigen::Vector3d(0.0, 0.0, 0.4)), 20);
  // A point of the back plane beside the front one: white.
  EXPECT_EQ(pixel(a, Eigen::Vector3d(0.15, 0.1, 0.6)), 235);
  // Off both rectangles; the plane behind the camera is not seen.
  EXPECT_EQ(int(a.At(2, 2)), 128);
}

TEST(BlobTexture, IsDeterministicSpansBlackToWhiteAndDependsOnTheSeed) {
  const Texture texture = BlobTexture(5);
  const Texture same = BlobTexture(5);
  const Texture other = BlobTexture(6);
  int dark = 0, bright = 0, differ = 0, n = 0;
  for (double y = -0.2; y < 0.2; y += 0.0013) {
    for (double x = -0.2; x < 0.2; x += 0.0017) {
      const double r = texture(x, y);
      ASSERT_GE(r, 0.0);
      ASSERT_LE(r, 1.0);
      ASSERT_EQ(r, same(x, y));
      dark += r < 0.2;
      bright += r > 0.8;
      differ += std::abs(r - other(x, y)) > 0.1;
      ++n;
    }
  }
  EXPECT_GT(dark, n / 6);
  EXPECT_GT(bright, n / 6);
  EXPECT_GT(differ, n / 2);
}

}  // namespace
}  // namespace hecal::testing
