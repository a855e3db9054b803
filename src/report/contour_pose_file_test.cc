#include "hecal/report/contour_pose_file.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <numbers>

namespace hecal::report {
namespace {

using nlohmann::json;

contour::ShapePose Result() {
  contour::ShapePose result;
  result.pose.translation << 1.0, 2.0, 3.0;
  result.pose.euler << std::numbers::pi / 2, 0.0, -std::numbers::pi / 4;
  result.pose.form = contour::RotationForm::kZyx;
  return result;
}

TEST(ContourPoseFile, PoseInRadiansAndDegrees) {
  const json doc = json::parse(ContourPoseJson(Result()));
  EXPECT_EQ(doc["translation"], json({1.0, 2.0, 3.0}));
  EXPECT_EQ(doc["rotation_matrix"][1], json({0.0, 1.0, 0.0}));
  EXPECT_NEAR(doc["euler_deg"][0].get<double>(), 90.0, 1e-12);
  EXPECT_NEAR(doc["euler_deg"][2].get<double>(), -45.0, 1e-12);
  EXPECT_EQ(doc["sequence"], "ZYX");
  EXPECT_EQ(doc["units"]["euler"], "rad");
  EXPECT_FALSE(doc.contains("covariance"));
  EXPECT_FALSE(doc.contains("bias"));
}

TEST(ContourPoseFile, UncertaintyNamesTheParametersOfTheForm) {
  contour::ShapePose result = Result();
  result.pose.form = contour::RotationForm::kZxz;
  contour::ContourPoseUncertainty ut;
  ut.mean << 1, 2, 3, 4, 5, 6;
  ut.parameters = ut.mean;
  ut.covariance = Matrix6d::Identity() * 4.0;
  ut.biased[4] = true;
  result.uncertainty = ut;
  const json doc = json::parse(ContourPoseJson(result));
  EXPECT_EQ(doc["sequence"], "ZXZ");
  EXPECT_EQ(doc["parameters"], json({"Tx", "Ty", "Tz", "phi", "theta", "psi"}));
  EXPECT_EQ(doc["ut_mean"], json({1.0, 2.0, 3.0, 4.0, 5.0, 6.0}));
  EXPECT_EQ(doc["covariance"][5][5], 4.0);
  EXPECT_EQ(doc["covariance"][5][4], 0.0);
  EXPECT_EQ(doc["bias"]["theta"], true);
  EXPECT_EQ(doc["bias"]["phi"], false);
}

}  // namespace
}  // namespace hecal::report
