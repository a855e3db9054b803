// The camera model: pinhole values by hand, the analytic Jacobian against central finite
// differences, and Undistort as the inverse of Project over the whole image, including strong
// distortion and the fold beyond which no preimage exists (nor one on a folded branch).
#include "hecal/pose/camera_model.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "hecal/core/error.h"
#include "hecal/core/random_draws.h"

namespace hecal::pose {
namespace {

CameraModel TestCamera(const std::array<double, 5>& distortion) {
  CameraModel camera;
  camera.fx = 800.0;
  camera.fy = 780.0;
  camera.cx = 640.5;
  camera.cy = 479.25;
  camera.width = 1280;
  camera.height = 960;
  camera.distortion = distortion;
  return camera;
}

// No distortion, mild (a typical webcam), strong barrel with tangential terms (a wide lens),
// and pincushion.
std::vector<CameraModel> TestCameras() {
  return {TestCamera({0.0, 0.0, 0.0, 0.0, 0.0}), TestCamera({-0.1, 0.05, 1e-3, -5e-4, 0.0}),
          TestCamera({-0.35, 0.12, 2e-3, -1.5e-3, -0.015}),
          TestCamera({0.25, 0.1, -1e-3, 1e-3, 0.02})};
}

TEST(CameraModel, PinholeIsTheSeedModel) {
  const CameraModel camera = CameraModel::Pinhole(1200.0);
  EXPECT_FALSE(camera.HasDistortion());
  const Eigen::Vector2d uv = Project(camera, Eigen::Vector3d(0.3, -0.2, 2.0));
  EXPECT_DOUBLE_EQ(uv.x(), 1200.0 * 0.3 / 2.0);
  EXPECT_DOUBLE_EQ(uv.y(), 1200.0 * -0.2 / 2.0);
}

TEST(CameraModel, DistortionByHand) {
  // x = 0.2, y = −0.1: r² = 0.05, radial = 1 + 0.1·0.05 + 0.01·0.0025 = 1.005025.
  CameraModel camera = TestCamera({0.1, 0.01, 0.002, 0.003, 0.0});
  const Eigen::Vector2d uv = Project(camera, Eigen::Vector3d(0.4, -0.2, 2.0));
  const double x_d = 0.2 * 1.005025 + 2 * 0.002 * 0.2 * -0.1 + 0.003 * (0.05 + 2 * 0.04);
  const double y_d = -0.1 * 1.005025 + 0.002 * (0.05 + 2 * 0.01) + 2 * 0.003 * 0.2 * -0.1;
  EXPECT_NEAR(uv.x(), 800.0 * x_d + 640.5, 1e-12);
  EXPECT_NEAR(uv.y(), 780.0 * y_d + 479.25, 1e-12);
  EXPECT_TRUE(camera.HasDistortion());
}

TEST(CameraModel, JacobianMatchesCentralDifferences) {
  std::mt19937_64 rng(11);
  hecal::UniformRealDistribution lateral(-0.6, 0.6), depth(0.3, 3.0);
  for (const CameraModel& camera : TestCameras()) {
    for (int trial = 0; trial < 200; ++trial) {
      const double z = depth(rng);
      const double y = lateral(rng) * z;  // y before x: the order the tests' data came in
      const double x = lateral(rng) * z;
      const Eigen::Vector3d X(x, y, z);
      Eigen::Matrix<double, 2, 3> J;
      const Eigen::Vector2d uv = Project(camera, X, &J);
      EXPECT_EQ(uv, Project(camera, X));
      Eigen::Matrix<double, 2, 3> numeric;
      for (int i = 0; i < 3; ++i) {
        const double h = 1e-6 * z;
        const Eigen::Vector3d dX = h * Eigen::Vector3d::Unit(i);
        numeric.col(i) = (Project(camera, X + dX) - Project(camera, X - dX)) / (2.0 * h);
      }
      // Central differences err by O(h²·f''') plus rounding O(ε·u/h): ~1e-5 of the entries.
      EXPECT_LT((J - numeric).cwiseAbs().maxCoeff(), 1e-5 * J.cwiseAbs().maxCoeff())
          << "camera k1 " << camera.distortion[0] << " point " << X.transpose();
    }
  }
}

// The intrinsics vector round-trips, and its Jacobian matches central differences (the
// projection is linear in fx, fy, cx, cy and the distortion coefficients, so the differences are
// exact up to rounding).
TEST(CameraModel, IntrinsicsJacobianMatchesCentralDifferences) {
  std::mt19937_64 rng(12);
  hecal::UniformRealDistribution lateral(-0.6, 0.6), depth(0.3, 3.0);
  for (const CameraModel& camera : TestCameras()) {
    const IntrinsicParameters k = IntrinsicsOf(camera);
    const CameraModel same = WithIntrinsics(camera, k.data());
    EXPECT_EQ(IntrinsicsOf(same), k);
    EXPECT_EQ(same.width, camera.width);
    for (int trial = 0; trial < 50; ++trial) {
      const double z = depth(rng);
      const double y = lateral(rng) * z;
      const double x = lateral(rng) * z;
      const Eigen::Vector3d X(x, y, z);
      const Eigen::Matrix<double, 2, kNumIntrinsics> J = ProjectionIntrinsicsJacobian(camera, X);
      for (int i = 0; i < kNumIntrinsics; ++i) {
        const double h = 1e-4 * std::max(1.0, std::abs(k(i)));
        IntrinsicParameters plus = k, minus = k;
        plus(i) += h;
        minus(i) -= h;
        const Eigen::Vector2d numeric = (Project(WithIntrinsics(camera, plus.data()), X) -
                                         Project(WithIntrinsics(camera, minus.data()), X)) /
                                        (2.0 * h);
        EXPECT_LT((J.col(i) - numeric).norm(), 1e-6 * (1.0 + numeric.norm())) << "parameter " << i;
      }
    }
  }
}

TEST(CameraModel, UndistortInvertsProjectAcrossTheImage) {
  for (const CameraModel& camera : TestCameras()) {
    double worst = 0.0;
    for (double u = -0.5; u <= camera.width - 0.5; u += camera.width / 40.0) {
      for (double v = -0.5; v <= camera.height - 0.5; v += camera.height / 30.0) {
        const Eigen::Vector2d pixel(u, v);
        const std::optional<Eigen::Vector2d> p = Undistort(camera, pixel);
        ASSERT_TRUE(p.has_value()) << "k1 " << camera.distortion[0] << " pixel " << u << ", " << v;
        worst = std::max(worst, (Project(camera, p->homogeneous()) - pixel).norm());
      }
    }
    EXPECT_LT(worst, 1e-9) << "k1 " << camera.distortion[0];
  }
}

TEST(CameraModel, UndistortOfProjectGivesTheRay) {
  std::mt19937_64 rng(5);
  hecal::UniformRealDistribution lateral(-0.6, 0.6);
  for (const CameraModel& camera : TestCameras()) {
    for (int trial = 0; trial < 200; ++trial) {
      const double y = lateral(rng);
      const double x = lateral(rng);
      const Eigen::Vector3d X(x, y, 1.0);
      const std::optional<Eigen::Vector2d> p = Undistort(camera, Project(camera, X));
      ASSERT_TRUE(p.has_value());
      EXPECT_LT((*p - X.head<2>()).norm(), 1e-11) << X.transpose();
    }
  }
}

TEST(CameraModel, UndistortRefusesPixelsBeyondTheFold) {
  // k1 = −0.5: r_d = r (1 − 0.5 r²) peaks at r = √(2/3), r_d = 0.544; farther out no preimage.
  const CameraModel camera = TestCamera({-0.5, 0.0, 0.0, 0.0, 0.0});
  EXPECT_TRUE(Undistort(camera, Eigen::Vector2d(640.5 + 800.0 * 0.5, 479.25)).has_value());
  EXPECT_FALSE(Undistort(camera, Eigen::Vector2d(640.5 + 800.0 * 0.6, 479.25)).has_value());
  // A point on the folded branch (r = 1.2 > √(2/3)) projects to a pixel whose physical
  // preimage is at r < √(2/3); Undistort returns that one, not the folded point.
  const Eigen::Vector2d folded_pixel = Project(camera, Eigen::Vector3d(1.2, 0.0, 1.0));
  const std::optional<Eigen::Vector2d> p = Undistort(camera, folded_pixel);
  ASSERT_TRUE(p.has_value());
  EXPECT_LT(p->norm(), std::sqrt(2.0 / 3.0));
  EXPECT_LT((Project(camera, p->homogeneous()) - folded_pixel).norm(), 1e-9);
  // Every pixel beyond the fold (r_d > 0.544) is refused, on a grid up to |x_d|, |y_d| = 2.
  // Gauss–Newton lands on the twice-folded branch (r > √2, radial factor 1 − 0.5 r² < 0: the ray
  // sent across the principal point) for some of them, where the determinant is positive again.
  int accepted = 0;
  for (double x_d = -2.0; x_d <= 2.0; x_d += 0.04) {
    for (double y_d = -2.0; y_d <= 2.0; y_d += 0.04) {
      if (std::hypot(x_d, y_d) < 0.55) continue;
      const Eigen::Vector2d pixel(640.5 + 800.0 * x_d, 479.25 + 780.0 * y_d);
      if (Undistort(camera, pixel).has_value()) ++accepted;
    }
  }
  EXPECT_EQ(accepted, 0);
}

TEST(CameraModel, UndistortPointsNamesTheFailingPoint) {
  const CameraModel camera = TestCamera({-0.5, 0.0, 0.0, 0.0, 0.0});
  const std::vector<Eigen::Vector2d> pixels = {{640.0, 480.0}, {700.0, 500.0}, {1200.0, 479.25}};
  try {
    UndistortPoints(camera, pixels);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("image point 3 at (1200, 479.25)"), std::string::npos)
        << e.what();
  }
  const std::vector<Eigen::Vector2d> normalised = UndistortPoints(camera, {pixels[0], pixels[1]});
  ASSERT_EQ(normalised.size(), 2u);
  EXPECT_LT((Project(camera, normalised[1].homogeneous()) - pixels[1]).norm(), 1e-9);
}

TEST(CameraModel, PixelRayIsTheUnitRayOfTheProjectedPointOrNamesThePixel) {
  const CameraModel camera = TestCamera({-0.1, 0.05, 1e-3, -5e-4, 0.0});
  const Eigen::Vector3d point(0.3, -0.2, 1.5);
  const Eigen::Vector3d ray = PixelRay(camera, Project(camera, point), "f.csv", 7);
  EXPECT_LT((ray - point.normalized()).norm(), 1e-10);
  const CameraModel folded = TestCamera({-0.5, 0.0, 0.0, 0.0, 0.0});
  try {
    PixelRay(folded, Eigen::Vector2d(1200.0, 479.25), "f.csv", 7);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "f.csv");
    EXPECT_EQ(e.line(), 7);
    EXPECT_NE(e.problem().find("pixel (1200.000000, 479.250000) cannot be undistorted"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace hecal::pose
