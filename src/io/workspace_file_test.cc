#include "hecal/io/workspace_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "hecal/core/error.h"
#include "testing/thrown.h"

namespace hecal::io {
namespace {

TEST(WorkspaceFile, ReadsMillimetresAndDefaults) {
  const Workspace w = ParseWorkspaceYaml(
      "units: mm\nposition_min: [300, -300, 150]\nposition_max: [800, 300, 700]\n"
      "hand_eye: [10, 20, 30, 1, 0, 0, 0]\ntarget: [500, 0, 0, 0, 1, 0, 0]\n",
      "w.yaml");
  EXPECT_NEAR(w.position_min.x(), 0.3, 1e-12);
  EXPECT_NEAR(w.position_max.z(), 0.7, 1e-12);
  EXPECT_NEAR(w.hand_eye->translation().z(), 0.03, 1e-12);
  EXPECT_NEAR(w.target->linear()(2, 2), -1.0, 1e-12);  // qx = 1: 180° about x
  EXPECT_NEAR(w.max_tilt, M_PI / 3.0, 1e-12);
  EXPECT_NEAR(w.nominal_translation_error, 0.02, 1e-12);
  // Contains: the box and the cone about straight down.
  Pose down = MakePose(w.target->linear(), Eigen::Vector3d(0.5, 0.0, 0.4));
  EXPECT_TRUE(w.Contains(down));
  down.translation().z() = 0.8;
  EXPECT_FALSE(w.Contains(down));
  EXPECT_FALSE(w.Contains(MakePose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.5, 0, 0.4))));
}

TEST(WorkspaceFile, MistakesNameTheLineAndTheFix) {
  const auto error = [](const std::string& text) {
    return std::string(
        testing::Thrown<InputError>([&] { ParseWorkspaceYaml(text, "w.yaml"); }).what());
  };
  EXPECT_NE(error("position_max: [1, 1, 1]\n").find("no 'position_min'"), std::string::npos);
  EXPECT_NE(error("position_min: [0, 0, 0]\nposition_max: [1, 1]\n").find("w.yaml:2"),
            std::string::npos);
  EXPECT_NE(error("position_min: [0, 0, 0]\nposition_max: [1, -1, 1]\n").find("along y"),
            std::string::npos);
  EXPECT_NE(error("position_min: [0, 0, 0]\nposition_max: [1, 1, 1]\nhand_eye: [0, 0, 0, 2, 0, "
                  "0, 0]\n")
                .find("norm"),
            std::string::npos);
  EXPECT_NE(error("position_min: [0, 0, 0]\nposition_max: [1, 1, 1]\nmax_tilt: 30\n")
                .find("max_tilt_deg"),
            std::string::npos);
}

}  // namespace
}  // namespace hecal::io
