#include "hecal/report/pose_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

namespace hecal::report {
namespace {

using nlohmann::json;

// T_camera_target: 90° about z, t = (0.1, 0.2, 0.3) m.
pose::PoseEstimate Estimate() {
  pose::PoseEstimate estimate;
  estimate.method = "dlt";
  estimate.T_camera_target = Pose::Identity();
  estimate.T_camera_target.linear() << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  estimate.T_camera_target.translation() << 0.1, 0.2, 0.3;
  estimate.residuals_px = {{0.5, -0.25}, {1.0, 2.0}};
  estimate.rms_px = 1.25;
  estimate.warnings = {"check the points"};
  return estimate;
}

TEST(PoseFile, LengthsInTheObjectUnitAndRotationInEveryForm) {
  const json doc =
      json::parse(PoseResultJson(Estimate(), {"a", std::nullopt}, io::LengthUnit::kMillimetre));
  EXPECT_EQ(doc["method"], "dlt");
  EXPECT_EQ(doc["units"]["length"], "mm");
  const json& T = doc["T_camera_target"];
  EXPECT_NEAR(T["translation"][0].get<double>(), 100.0, 1e-9);
  EXPECT_NEAR(T["translation"][2].get<double>(), 300.0, 1e-9);
  EXPECT_NEAR(T["matrix"][1][3].get<double>(), 200.0, 1e-9);
  EXPECT_NEAR(T["matrix"][0][1].get<double>(), -1.0, 1e-12);
  EXPECT_EQ(T["matrix"][3], json({0.0, 0.0, 0.0, 1.0}));
  EXPECT_NEAR(T["quaternion_wxyz"][0].get<double>(), std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(T["quaternion_wxyz"][3].get<double>(), std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(T["rotation_vector"][2].get<double>(), std::numbers::pi / 2, 1e-12);
  EXPECT_EQ(doc["reprojection_rms_px"], 1.25);
  EXPECT_FALSE(doc.contains("covariance"));  // not refined
  // A point with an id keeps it; one without is numbered from 1.
  EXPECT_EQ(doc["points"][0]["id"], "a");
  EXPECT_EQ(doc["points"][1]["id"], 2);
  EXPECT_EQ(doc["points"][1]["residual_px"], json({1.0, 2.0}));
  EXPECT_EQ(doc["warnings"], json({"check the points"}));
}

TEST(PoseFile, CovarianceIsScaledToTheUnitAndSymmetric) {
  pose::PoseEstimate estimate = Estimate();
  Matrix6d C = Matrix6d::Identity() * 1e-6;
  C(0, 3) = 2e-6;  // rad·m, asymmetric on purpose
  estimate.covariance = C;
  estimate.sigma_px = 0.5;
  estimate.sigma_source = pose::SigmaSource::kGiven;
  const json doc = json::parse(PoseResultJson(estimate, {"a", "b"}, io::LengthUnit::kMillimetre));
  const json& M = doc["covariance"]["matrix"];
  EXPECT_NEAR(M[0][0].get<double>(), 1e-6, 1e-18);  // rad²
  EXPECT_NEAR(M[3][3].get<double>(), 1.0, 1e-12);   // 1e-6 m² = 1 mm²
  EXPECT_NEAR(M[0][3].get<double>(), 1e-3, 1e-15);  // (2e-6 + 0)/2 rad·m = 1e-3 rad·mm
  EXPECT_EQ(M[0][3], M[3][0]);
  EXPECT_EQ(doc["covariance"]["pixel_sigma"], 0.5);
  EXPECT_EQ(doc["covariance"]["pixel_sigma_source"], "given");
  EXPECT_EQ(doc["covariance"]["parameterization"], "right, (rx,ry,rz,tx,ty,tz)");
}

}  // namespace
}  // namespace hecal::report
