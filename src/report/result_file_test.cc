#include "hecal/report/result_file.h"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>

#include "hecal/geometry/se3.h"

namespace hecal::report {
namespace {

using nlohmann::json;

ResultDocument MakeDocument() {
  ResultDocument document;
  document.setup = handeye::Setup::kEyeToHand;
  document.unit = io::LengthUnit::kMillimetre;
  document.station_ids = {"a", "b", "c"};
  document.rejected = {1};
  estimation::CalibrationResult result;
  result.method = estimation::Method::kParkMartin;
  result.X = se3::Exp((Vector6d() << 0.1, 0.2, -0.3, 1.0, -2.0, 0.5).finished());
  result.Z = se3::Exp((Vector6d() << -0.5, 0.0, 0.25, 0.01, 0.02, 0.03).finished());
  Matrix6d covariance = Matrix6d::Identity() * 1e-6;
  // m², must become 0.5 mm² (a correlation of 0.5: the covariance is positive definite)
  covariance(3, 4) = covariance(4, 3) = 0.5e-6;
  estimation::CalibrationCovariance joint;
  joint.method = estimation::CovarianceMethod::kUnscented;
  joint.solves = 13;
  joint.covariance.setZero();
  joint.covariance.topLeftCorner<6, 6>() = covariance;
  joint.covariance.bottomRightCorner<6, 6>() = covariance;
  joint.covariance(0, 6) = joint.covariance(6, 0) = 3e-7;  // cross term, rad²
  result.covariance = joint;
  result.residuals = {{0.01, 0.002, 0.9, false}, {0.02, 0.004, 4.0, true}};
  result.rotation_rms = 0.0158;
  result.translation_rms = 0.0032;
  result.warnings = {"noise estimated"};
  document.results = {result};
  return document;
}

TEST(ResultFile, JsonFollowsTheContract) {
  const ResultDocument document = MakeDocument();
  const json j = json::parse(FormatResult(document, ResultFormat::kJson));
  EXPECT_EQ(j["setup"], "eye-to-hand");
  EXPECT_EQ(j["method"], "park-martin");
  EXPECT_EQ(j["units"]["length"], "mm");
  EXPECT_EQ(j["units"]["angle"], "rad");
  EXPECT_EQ(j["X"]["frame"], "T_base_camera");
  EXPECT_EQ(j["Z"]["frame"], "T_gripper_target");
  // Translations in mm, in the matrix and the translation field alike.
  const Pose& X = document.results[0].X;
  for (int r = 0; r < 3; ++r) {
    EXPECT_NEAR(j["X"]["translation"][r].get<double>(), 1000.0 * X.translation()(r), 1e-9);
    EXPECT_NEAR(j["X"]["matrix"][r][3].get<double>(), 1000.0 * X.translation()(r), 1e-9);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(j["X"]["matrix"][r][c].get<double>(), X.linear()(r, c), 1e-15);
    }
  }
  EXPECT_EQ(j["X"]["matrix"][3], json({0.0, 0.0, 0.0, 1.0}));
  // Quaternion (w, x, y, z) reproduces the rotation.
  const auto& q = j["X"]["quaternion_wxyz"];
  const Eigen::Quaterniond quaternion(q[0].get<double>(), q[1].get<double>(), q[2].get<double>(),
                                      q[3].get<double>());
  EXPECT_LT((quaternion.toRotationMatrix() - X.linear()).norm(), 1e-12);
  // Covariance: rotation block unchanged, translation block scaled to mm².
  EXPECT_NEAR(j["covariance"]["X"][0][0].get<double>(), 1e-6, 1e-18);
  EXPECT_NEAR(j["covariance"]["X"][3][3].get<double>(), 1.0, 1e-12);
  EXPECT_NEAR(j["covariance"]["X"][3][4].get<double>(), 0.5, 1e-12);
  EXPECT_EQ(j["covariance"]["parameterization"], "right, (rx,ry,rz,tx,ty,tz)");
  EXPECT_EQ(j["covariance"]["method"], "unscented");
  EXPECT_EQ(j["covariance"]["solves"], 13);
  EXPECT_NEAR(j["covariance"]["XZ"][0][0].get<double>(), 3e-7, 1e-20);
  // 1σ per axis: sqrt(1e-6) rad = 0.0573°, sqrt(1 mm²) = 1 mm.
  EXPECT_NEAR(j["covariance"]["sigma"]["X"]["rotation_deg"][2].get<double>(),
              1e-3 * 180.0 / std::numbers::pi, 1e-12);
  EXPECT_NEAR(j["covariance"]["sigma"]["Z"]["translation"][0].get<double>(), 1.0, 1e-12);
  // t's 1σ along the parent frame's axes (eye-to-hand: X's is the base, Z's the gripper):
  // sqrt of the diagonal of R̂ C_vv R̂ᵀ, in mm.
  const Eigen::Matrix3d C_vv = document.results[0].covariance->X().bottomRightCorner<3, 3>();
  const auto& in_parent_x = j["covariance"]["sigma"]["X"]["translation_in_parent"];
  const auto& in_parent_z = j["covariance"]["sigma"]["Z"]["translation_in_parent"];
  EXPECT_EQ(in_parent_x["frame"], "base");
  EXPECT_EQ(in_parent_z["frame"], "gripper");
  const Eigen::Matrix3d C_x = X.linear() * C_vv * X.linear().transpose();
  const Eigen::Matrix3d& R_z = document.results[0].Z.linear();
  const Eigen::Matrix3d C_z = R_z * C_vv * R_z.transpose();
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(in_parent_x["translation"][k].get<double>(), 1e3 * std::sqrt(C_x(k, k)), 1e-9);
    EXPECT_NEAR(in_parent_z["translation"][k].get<double>(), 1e3 * std::sqrt(C_z(k, k)), 1e-9);
  }
  EXPECT_FALSE(j["covariance"].contains("samples"));  // Monte Carlo only
  // Residuals skip the rejected station; rotation in degrees, translation in mm.
  EXPECT_EQ(j["stations"]["used"], json({"a", "c"}));
  EXPECT_EQ(j["stations"]["rejected"], json({"b"}));
  ASSERT_EQ(j["residuals"]["per_station"].size(), 2u);
  EXPECT_EQ(j["residuals"]["per_station"][1]["id"], "c");
  EXPECT_NEAR(j["residuals"]["per_station"][1]["rotation_deg"].get<double>(), 0.02 * 180.0 / M_PI,
              1e-12);
  EXPECT_NEAR(j["residuals"]["per_station"][1]["translation"].get<double>(), 4.0, 1e-12);
  EXPECT_TRUE(j["residuals"]["per_station"][1]["outlier"].get<bool>());
  EXPECT_NEAR(j["residuals"]["translation_rms"].get<double>(), 3.2, 1e-12);
  EXPECT_EQ(j["warnings"], json({"noise estimated"}));
}

TEST(ResultFile, AllMethodsWritesAResultsArray) {
  ResultDocument document = MakeDocument();
  document.all_methods = true;
  document.results.push_back(document.results[0]);
  document.results[1].method = estimation::Method::kMl;
  const json j = json::parse(FormatResult(document, ResultFormat::kJson));
  ASSERT_TRUE(j.contains("results"));
  ASSERT_EQ(j["results"].size(), 2u);
  EXPECT_EQ(j["results"][1]["method"], "ml");
}

TEST(ResultFile, AllMethodsListsAMethodThatRefusedWithItsReason) {
  ResultDocument document = MakeDocument();
  document.all_methods = true;
  document.failures.push_back({estimation::Method::kDaniilidis, "inconsistent motions"});
  const json j = json::parse(FormatResult(document, ResultFormat::kJson));
  ASSERT_EQ(j["results"].size(), 2u);
  EXPECT_EQ(j["results"][1]["method"], "daniilidis");
  EXPECT_EQ(j["results"][1]["error"], "inconsistent motions");
  EXPECT_FALSE(j["results"][1].contains("X"));
}

TEST(ResultFile, YamlCarriesTheSameValues) {
  const ResultDocument document = MakeDocument();
  const json j = json::parse(FormatResult(document, ResultFormat::kJson));
  const YAML::Node y = YAML::Load(FormatResult(document, ResultFormat::kYaml));
  EXPECT_EQ(y["method"].as<std::string>(), "park-martin");
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) {
      EXPECT_EQ(y["X"]["matrix"][r][c].as<double>(), j["X"]["matrix"][r][c].get<double>());
    }
  }
  EXPECT_EQ(y["stations"]["rejected"][0].as<std::string>(), "b");
}

TEST(ResultFile, FormatFollowsTheExtension) {
  EXPECT_EQ(ResultFormatForPath("out/result.yaml"), ResultFormat::kYaml);
  EXPECT_EQ(ResultFormatForPath("r.yml"), ResultFormat::kYaml);
  EXPECT_EQ(ResultFormatForPath("r.json"), ResultFormat::kJson);
  EXPECT_EQ(ResultFormatForPath("result"), ResultFormat::kJson);
}

TEST(ResultFile, WriteIsAtomicAndReportsAMissingDirectory) {
  const auto dir = std::filesystem::temp_directory_path() / "hecal_result_file_test";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "result.json").string();
  WriteResult(path, MakeDocument());
  std::ifstream in(path);
  EXPECT_EQ(json::parse(in)["method"], "park-martin");
  EXPECT_THROW(WriteResult((dir / "missing" / "result.json").string(), MakeDocument()),
               std::exception);
  EXPECT_FALSE(std::filesystem::exists(dir / "missing"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace hecal::report
