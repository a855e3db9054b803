// The target-free calibration job on synthetic scenes whose X is known (testing/
// epipolar_scenes.h): noise-free matches give the true X with a closed certificate; a planted
// wrong match is removed and named by its stations and id; the result file holds X as solved
// and the 1σ of its translation along the hand's axes; the options name the bad field; the
// correspondence reader numbers stations by row.
#include "hecal/jobs/global_calibration.h"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "hecal/core/error.h"
#include "hecal/geometry/se3.h"
#include "testing/epipolar_scenes.h"
#include "testing/options_validity.h"
#include "testing/scratch_folder.h"

namespace hecal::jobs {
namespace {

GlobalMatches MatchesOf(const testing::EpipolarScene& scene, double focal) {
  GlobalMatches matches;
  matches.T_base_gripper = scene.T_base_gripper;
  matches.focal = focal;
  for (const global::EpipolarMotion& motion : scene.problem.motions) {
    matches.motions.push_back({motion.first_station, motion.second_station,
                               std::to_string(motion.first_station),
                               std::to_string(motion.second_station), motion.pairs});
  }
  return matches;
}

testing::EpipolarSceneSpec SmallSpec(handeye::Setup setup) {
  testing::EpipolarSceneSpec spec;
  spec.motions = 4;
  spec.pairs = 20;
  spec.setup = setup;
  return spec;
}

TEST(CalibrateGlobal, RecoversTheTrueXInBothSetupsWithACertificate) {
  for (const handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    const testing::EpipolarSceneSpec spec = SmallSpec(setup);
    const testing::EpipolarScene scene = testing::MakeEpipolarScene(spec, 12);
    report::GlobalCalibrationOptions options;
    options.setup = setup;
    options.epsilon = 1e-5;
    options.reach = 1.0;
    const report::GlobalCalibrationResult result =
        CalibrateGlobal(MatchesOf(scene, spec.focal), options);
    EXPECT_LT(se3::Log(result.robot_noise.polish.X.inverse() * scene.X).norm(), 1e-6);
    EXPECT_LE(result.certificate.upper - result.certificate.lower, 1e-5);
    EXPECT_EQ(result.inliers, spec.motions * spec.pairs);
    EXPECT_TRUE(result.removed.empty());
    EXPECT_DOUBLE_EQ(result.pixel_threshold, 4.0 * std::sqrt(2.0) * 0.5 / spec.focal);
  }
}

TEST(CalibrateGlobal, RemovesAPlantedWrongMatchAndNamesIt) {
  const testing::EpipolarSceneSpec spec = SmallSpec(handeye::Setup::kEyeInHand);
  const testing::EpipolarScene scene = testing::MakeEpipolarScene(spec, 12);
  GlobalMatches matches = MatchesOf(scene, spec.focal);
  global::BearingPair& wrong = matches.motions[2].pairs[5];
  wrong.second = (wrong.second + Eigen::Vector3d(0.1, -0.05, 0.0)).normalized();
  report::GlobalCalibrationOptions options;
  options.reach = 1.0;
  const report::GlobalCalibrationResult result = CalibrateGlobal(matches, options);
  ASSERT_EQ(result.removed.size(), 1u);
  EXPECT_EQ(result.removed[0].first, "4");
  EXPECT_EQ(result.removed[0].second, "5");
  EXPECT_EQ(result.removed[0].id, wrong.id);
  EXPECT_EQ(result.inliers, spec.motions * spec.pairs - 1);
  EXPECT_LT(se3::Log(result.robot_noise.polish.X.inverse() * scene.X).norm(), 1e-6);

  const nlohmann::json doc = nlohmann::json::parse(report::GlobalResultJson(result));
  EXPECT_EQ(doc["method"], "global");
  EXPECT_EQ(doc["setup"], "eye-in-hand");
  for (int r = 0; r < 3; ++r) {
    EXPECT_EQ(doc["X"]["translation_m"][r].get<double>(),
              result.robot_noise.polish.X.translation()[r]);
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(doc["X"]["rotation"][r][c].get<double>(),
                result.robot_noise.polish.X.linear()(r, c));
    }
  }
  EXPECT_EQ(doc["matches"]["removed"].size(), 1u);
  EXPECT_EQ(doc["matches"]["removed"][0]["id"].get<int>(), wrong.id);
  EXPECT_EQ(doc["certificate"]["certified"].get<bool>(), result.certificate.certified);
}

// The file's 1σ of t along the hand's axes is √diag(R̂ C_tt R̂ᵀ) of its own X and covariance
// (report/translation_sigma.h), not the covariance's own (camera) axes.
TEST(CalibrateGlobal, WritesTheTranslationSigmaAlongTheHandAxes) {
  testing::EpipolarSceneSpec spec = SmallSpec(handeye::Setup::kEyeInHand);
  spec.pixel_sigma = 0.5;
  const testing::EpipolarScene scene = testing::MakeEpipolarScene(spec, 12);
  report::GlobalCalibrationOptions options;
  options.reach = 1.0;
  options.max_cubes = 2000;  // the search's bounds do not matter here: the polish is the answer
  const nlohmann::json doc = nlohmann::json::parse(
      report::GlobalResultJson(CalibrateGlobal(MatchesOf(scene, spec.focal), options)));
  Eigen::Matrix3d R;
  Matrix6d C;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) R(r, c) = doc["X"]["rotation"][r][c].get<double>();
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 6; ++c) C(r, c) = doc["covariance"]["X"][r][c].get<double>();
  const Eigen::Vector3d expected =
      (R * C.bottomRightCorner<3, 3>() * R.transpose()).diagonal().cwiseSqrt();
  const Eigen::Vector3d own_axes = C.bottomRightCorner<3, 3>().diagonal().cwiseSqrt();
  const nlohmann::json& parent = doc["covariance"]["translation_in_parent"];
  EXPECT_EQ(parent["frame"], "gripper");
  ASSERT_GT(expected.minCoeff(), 0.0);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(parent["translation"][k].get<double>(), expected[k], 1e-12 * expected[k]);
  // The scene's X turns the axes, so the two readings differ: the test can tell them apart.
  EXPECT_GT((expected - own_axes).cwiseAbs().maxCoeff(), 0.05 * expected.maxCoeff());
}

// A search stopped by its budget still returns X, with the bounds proved, why it stopped, and a
// warning that says so.
TEST(CalibrateGlobal, SaysWhyTheSearchStoppedAndWarnsWhenABudgetEndedIt) {
  testing::EpipolarSceneSpec spec = SmallSpec(handeye::Setup::kEyeInHand);
  spec.pixel_sigma = 0.5;
  const testing::EpipolarScene scene = testing::MakeEpipolarScene(spec, 12);
  report::GlobalCalibrationOptions options;
  options.reach = 1.0;
  options.epsilon = 1e-7;
  options.relative_gap = 0.0;
  options.max_cubes = 1;
  const report::GlobalCalibrationResult result =
      CalibrateGlobal(MatchesOf(scene, spec.focal), options);
  const nlohmann::json doc = nlohmann::json::parse(report::GlobalResultJson(result));
  const nlohmann::json& c = doc["certificate"];
  EXPECT_EQ(c["stopped_by"], "max cubes");
  EXPECT_FALSE(c["certified"].get<bool>());
  EXPECT_LE(c["lower"].get<double>(), c["upper"].get<double>());
  EXPECT_EQ(c["max_cubes"], 1);
  EXPECT_EQ(c["time_budget_s"], 120.0);
  ASSERT_GE(doc["warnings"].size(), 1u);  // the search's first (the model check's may follow)
  EXPECT_NE(doc["warnings"][0].get<std::string>().find("--max-cubes"), std::string::npos);
  // The polish does not need a certified start: X is within 5σ of the truth per axis.
  const estimation::EpipolarPolish& polish = result.robot_noise.polish;
  const Vector6d error = se3::Log(polish.X.inverse() * scene.X);
  for (int k = 0; k < 6; ++k)
    EXPECT_LT(std::abs(error[k]), 5.0 * std::sqrt(polish.covariance(k, k)));
}

// covariance.model_check (global_calibration_check.h): the jackknife's fields, and the covariance
// written is the model's scaled by the inflation factors (the model's own when nothing is used).
TEST(CalibrateGlobal, WritesTheModelCheckUnderTheCovariance) {
  testing::EpipolarSceneSpec spec = SmallSpec(handeye::Setup::kEyeInHand);
  spec.pixel_sigma = 0.5;
  const testing::EpipolarScene scene = testing::MakeEpipolarScene(spec, 12);
  report::GlobalCalibrationOptions options;
  options.reach = 1.0;
  options.max_cubes = 2000;  // the check needs the polish, not a closed certificate
  const report::GlobalCalibrationResult result =
      CalibrateGlobal(MatchesOf(scene, spec.focal), options);
  const nlohmann::json doc = nlohmann::json::parse(report::GlobalResultJson(result));
  const nlohmann::json& check = doc["covariance"]["model_check"];
  EXPECT_EQ(check["method"], "jackknife");
  ASSERT_TRUE(check["possible"].get<bool>()) << check.dump();
  EXPECT_EQ(check["groups"].get<int>(), 8);  // 4 motions, 8 stations, one group each
  Vector6d inflation;
  Matrix6d model, written;
  for (int k = 0; k < 3; ++k) {
    inflation[k] = check["inflation"]["X"]["rotation"][k].get<double>();
    inflation[k + 3] = check["inflation"]["X"]["translation"][k].get<double>();
  }
  for (int r = 0; r < 6; ++r) {
    for (int c = 0; c < 6; ++c) {
      model(r, c) = check["model_X"][r][c].get<double>();
      written(r, c) = doc["covariance"]["X"][r][c].get<double>();
    }
  }
  const bool used = check["used"].get<bool>();
  EXPECT_EQ(used, !check["flagged"].empty());
  if (!used) inflation.setOnes();
  const Matrix6d expected = inflation.asDiagonal() * model * inflation.asDiagonal();
  EXPECT_LT((written - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff());
  bool warned = false;
  for (const std::string& warning : result.warnings)
    warned = warned || warning.find("jackknife") != std::string::npos;
  EXPECT_EQ(warned, used);
}

TEST(CalibrateGlobal, RefusesAMotionNamingNoStation) {
  const testing::EpipolarScene scene =
      testing::MakeEpipolarScene(SmallSpec(handeye::Setup::kEyeInHand), 12);
  GlobalMatches matches = MatchesOf(scene, 1000.0);
  matches.motions[1].second = int(matches.T_base_gripper.size());
  EXPECT_THROW(CalibrateGlobal(matches, {}), InputError);
}

TEST(GlobalCalibrationOptions, NameTheBadField) {
  const report::GlobalCalibrationOptions options;
  EXPECT_TRUE(testing::IsValidOptions(options));
  using O = report::GlobalCalibrationOptions;
  EXPECT_TRUE(testing::RefusesNaming(options, "GlobalCalibrationOptions.epsilon",
                                     [](O& o) { o.epsilon = 0.0; }));
  EXPECT_TRUE(testing::RefusesNaming(options, "GlobalCalibrationOptions.epsilon",
                                     [](O& o) { o.epsilon = 1.5; }));
  EXPECT_TRUE(testing::RefusesNaming(options, "GlobalCalibrationOptions.relative_gap",
                                     [](O& o) { o.relative_gap = 1.0; }));
  EXPECT_TRUE(testing::RefusesNaming(options, "GlobalCalibrationOptions.reach",
                                     [](O& o) { o.reach = 0.0; }));
  EXPECT_TRUE(testing::RefusesNaming(options, "GlobalCalibrationOptions.max_cubes",
                                     [](O& o) { o.max_cubes = 0; }));
  EXPECT_TRUE(testing::RefusesNaming(options, "GlobalCalibrationOptions.time_budget",
                                     [](O& o) { o.time_budget = 0.0; }));
  EXPECT_TRUE(testing::RefusesNaming(options, "GlobalCalibrationOptions.time_budget",
                                     [](O& o) { o.time_budget = INFINITY; }));
  EXPECT_TRUE(testing::RefusesNaming(options, "GlobalCalibrationOptions.matches_per_motion",
                                     [](O& o) { o.matches_per_motion = 7; }));
  EXPECT_TRUE(testing::RefusesNaming(options, "GlobalCalibrationOptions.threads",
                                     [](O& o) { o.threads = -1; }));
  EXPECT_TRUE(testing::RefusesNaming(options, "GlobalCalibrationOptions.pixel_sigma",
                                     [](O& o) { o.pixel_sigma = 0.0; }));
  EXPECT_TRUE(testing::RefusesNaming(options, "GlobalCalibrationOptions.pixel_sigma",
                                     [](O& o) { o.pixel_sigma = 101.0; }));
  EXPECT_TRUE(testing::RefusesNaming(options, "GlobalCalibrationOptions.robot_sigma", [](O& o) {
    o.robot_sigma = estimation::PoseSigma{-1.0, 0.0};
  }));
}

class GlobalFiles : public testing::ScratchFolderTest {
 protected:
  GlobalFiles() : ScratchFolderTest("hecal_global") {}
};

// Robot rows without ids are stations 1, 2, …; pixels become unit rays through the camera.
TEST_F(GlobalFiles, NumbersStationsByRowAndTurnsPixelsIntoRays) {
  const std::string robot = Write("robot.csv",
                                  "x,y,z,qw,qx,qy,qz\n0,0,0,1,0,0,0\n0.1,0,0,1,0,0,0\n"
                                  "0.2,0,0,1,0,0,0\n");
  const std::string pixels = Write("pixels.csv", "first,second,u1,v1,u2,v2\n2,3,420,240,320,340\n");
  const std::string camera =
      Write("camera.yaml",
            "fx: 1000\nfy: 1000\ncx: 320\ncy: 240\nwidth: 640\nheight: 480\n"
            "distortion: {model: plumb_bob, coefficients: [0, 0, 0, 0, 0]}\n");
  const GlobalMatches matches = ReadGlobalMatches(robot, {}, pixels, camera);
  ASSERT_EQ(matches.T_base_gripper.size(), 3u);
  EXPECT_DOUBLE_EQ(matches.T_base_gripper[2].translation().x(), 0.2);
  EXPECT_EQ(matches.focal, 1000.0);
  ASSERT_EQ(matches.motions.size(), 1u);
  EXPECT_EQ(matches.motions[0].first, 1);
  EXPECT_EQ(matches.motions[0].second, 2);
  EXPECT_EQ(matches.motions[0].first_name, "2");
  ASSERT_EQ(matches.motions[0].pairs.size(), 1u);
  EXPECT_LT((matches.motions[0].pairs[0].first - Eigen::Vector3d(0.1, 0, 1).normalized()).norm(),
            1e-12);
  EXPECT_LT((matches.motions[0].pairs[0].second - Eigen::Vector3d(0, 0.1, 1).normalized()).norm(),
            1e-12);
  // Pixels need the camera; a station beyond the rows is named with its line.
  EXPECT_THROW(ReadGlobalMatches(robot, {}, pixels, ""), InputError);
  const std::string beyond = Write("beyond.csv", "first,second,u1,v1,u2,v2\n3,4,0,0,0,0\n");
  try {
    ReadGlobalMatches(robot, {}, beyond, camera);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 2);
    EXPECT_NE(e.problem().find("station '4'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace hecal::jobs
