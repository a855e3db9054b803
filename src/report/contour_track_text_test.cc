// The per-frame line of `contour track` against lines written by hand: a lost frame without a
// pose, and a tracked frame with T = (1.5, −2, 30) and angles of 0.1, −0.2 and 0.3 rad
// (5.730°, −11.459°, 17.189°), named by the rotation form, with and without the bias flag.
#include "hecal/report/contour_track_text.h"

#include <gtest/gtest.h>

#include <string>

namespace hecal::report {
namespace {

TEST(ContourTrackText, LostFrameWithoutPose) {
  contour::TrackedImage image;
  image.image = "frame_0003.png";
  image.frame.status = contour::FrameStatus::kLost;
  image.frame.tracked.frame = 3;
  image.frame.tracked.edges_used = 5;
  image.frame.tracked.edges_searched = 120;
  image.frame.tracked.sigma = 0.4376;
  EXPECT_EQ(ContourTrackLine(image, contour::RotationForm::kZyx),
            "   3 frame_0003.png           lost     edges   5/120  σ 0.438 px\n");
}

TEST(ContourTrackText, TrackedFrameWithPose) {
  contour::TrackedImage image;
  image.image = "a.png";
  image.frame.tracked.frame = 12;
  image.frame.tracked.edges_used = 96;
  image.frame.tracked.edges_searched = 100;
  image.frame.tracked.sigma = 0.25;
  contour::ContourPoseUncertainty pose;
  pose.parameters << 1.5, -2.0, 30.0, 0.1, -0.2, 0.3;
  pose.mean.setZero();
  pose.covariance.setZero();
  pose.any_biased = true;
  image.frame.pose = pose;
  EXPECT_EQ(ContourTrackLine(image, contour::RotationForm::kZyx),
            "  12 a.png                    tracked  edges  96/100  σ 0.250 px  T = (1.500, -2.000, "
            "30.000)  Rx,Ry,Rz = (5.730, -11.459, 17.189)°  (bias)\n");
  image.frame.pose->any_biased = false;
  EXPECT_EQ(ContourTrackLine(image, contour::RotationForm::kZxz),
            "  12 a.png                    tracked  edges  96/100  σ 0.250 px  T = (1.500, -2.000, "
            "30.000)  phi,theta,psi = (5.730, -11.459, 17.189)°\n");
}

}  // namespace
}  // namespace hecal::report
