#include "hecal/report/contour_track_file.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

namespace hecal::report {
namespace {

using nlohmann::json;

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> Fields(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, ',')) fields.push_back(field);
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

// Two frames: one tracked with a pose (Rx 0.5 rad, σ(Ry) 0.1 rad, Ry flagged biased), one
// singular (no pose).
ContourTrack Track() {
  ContourTrack track;
  track.options.camera.focal = 800.0;
  track.options.camera.z0 = 1500.0;
  track.options.principal << 320.0, 240.0;
  track.options.perspective = true;
  track.options.tracker.subspace = contour::ShapeSubspace::kSimilarity;
  track.template_shape << 1, 2, 3, 4, 5, 6;
  track.polarity = -1;
  contour::TrackedImage first;
  first.image = "a,1.png";
  first.frame.tracked.frame = 0;
  first.frame.tracked.edges_used = 40;
  first.frame.tracked.edges_searched = 50;
  first.frame.tracked.sigma = 0.5;
  first.frame.tracked.shape << 3.0, 0, 0, 0, 0, 0;
  first.frame.tracked.shape_covariance = Matrix6d::Identity() * 4.0;
  contour::ContourPoseUncertainty pose;
  pose.parameters << 10.0, 20.0, 30.0, 0.5, 0.0, 0.0;
  pose.covariance = Matrix6d::Identity() * 0.01;
  pose.mean = pose.parameters;
  pose.biased[4] = true;
  first.frame.pose = pose;
  contour::TrackedImage second;
  second.image = "b.png";
  second.frame.tracked.frame = 1;
  second.frame.status = contour::FrameStatus::kSingular;
  track.frames = {first, second};
  return track;
}

TEST(ContourTrackFile, CsvHasOneFullRowPerFrame) {
  const std::vector<std::string> lines = Lines(ContourTrackCsv(Track()));
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0].rfind("# hecal ", 0), 0u);
  EXPECT_NE(lines[0].find("(Z0 = 1500); pose model perspective"), std::string::npos);
  const std::vector<std::string> header = Fields(lines[1]);
  ASSERT_EQ(header.size(), 7u + 6 + 6 + 6 + 6 + 1);
  EXPECT_EQ(header[7], "tx");
  EXPECT_EQ(header[22], "Rx_deg");
  EXPECT_EQ(header[31], "bias");
  // The quoted image name holds a comma: compare the row from the quote on.
  const std::string& row = lines[2];
  EXPECT_EQ(row.rfind("0,\"a,1.png\",tracked,40,50,0.5,", 0), 0u);
  const std::vector<std::string> fields = Fields(row.substr(row.find('"', 3) + 2));
  ASSERT_EQ(fields.size(), header.size() - 2);
  EXPECT_EQ(fields[5], "3");                                       // tx
  EXPECT_EQ(fields[11], "2");                                      // sd_tx = √4
  EXPECT_DOUBLE_EQ(std::stod(fields[20]), 90 / std::numbers::pi);  // Rx in degrees
  EXPECT_EQ(fields[29], "Ry");                                     // the biased parameter
  const std::vector<std::string> singular = Fields(lines[3]);
  ASSERT_EQ(singular.size(), header.size());
  EXPECT_EQ(singular[2], "singular");
  for (std::size_t i = 19; i < 31; ++i) EXPECT_EQ(singular[i], "") << header[i];
}

TEST(ContourTrackFile, JsonHoldsTheSetUpAndEveryFrame) {
  const json doc = json::parse(ContourTrackJson(Track()));
  EXPECT_EQ(doc["pose_model"], "perspective");
  EXPECT_EQ(doc["subspace"], "similarity");
  EXPECT_EQ(doc["camera"]["principal_point"], json({320.0, 240.0}));
  EXPECT_EQ(doc["rotation"]["sequence"], "ZYX");
  EXPECT_EQ(doc["template_shape"], json({1.0, 2.0, 3.0, 4.0, 5.0, 6.0}));
  EXPECT_EQ(doc["polarity"], -1);
  ASSERT_EQ(doc["frames"].size(), 2u);
  const json& first = doc["frames"][0];
  EXPECT_EQ(first["image"], "a,1.png");
  EXPECT_EQ(first["edges"]["used"], 40);
  EXPECT_NEAR(first["pose"]["euler_deg"][2].get<double>(), 0.0, 1e-12);
  EXPECT_EQ(first["pose"]["bias"]["Ry"], true);
  EXPECT_EQ(first["pose"]["covariance"][3][3], 0.01);
  EXPECT_EQ(doc["frames"][1]["status"], "singular");
  EXPECT_FALSE(doc["frames"][1].contains("pose"));
}

}  // namespace
}  // namespace hecal::report
