// OpenCV 4.6 as a peer (calibrateHandEye DANIILIDIS and ANDREFF) on identical data.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "hecal/handeye/andreff.h"
#include "hecal/handeye/daniilidis.h"
#include "testing/handeye_solver_suite.h"
#include "testing/opencv_handeye.h"

namespace hecal::handeye {
namespace {

using testing::Degrees;
using testing::Error;

struct Peer {
  const char* name;
  Pose (*hecal)(const std::vector<Motion>&);
  cv::HandEyeCalibrationMethod opencv;
};

const Peer kPeers[] = {
    {"daniilidis", SolveDaniilidis, cv::CALIB_HAND_EYE_DANIILIDIS},
    {"andreff", SolveAndreff, cv::CALIB_HAND_EYE_ANDREFF},
};

// Moderate rotations (no pair near π), where both implementations work: noise-free they agree to
// rounding.
TEST(DaniilidisAndreffOpenCvPeer, AgreeOnNoiseFreeBenignData) {
  for (const Peer& peer : kPeers) {
    double worst = 0.0;
    for (handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
      for (uint64_t seed = 1; seed <= 10; ++seed) {
        const Problem problem = testing::BenignCase(setup, 10, seed).MeasuredProblem();
        const testing::PoseError e = Error(peer.hecal(AllPairMotions(problem)),
                                           testing::OpenCvHandEye(problem, peer.opencv));
        worst = std::max({worst, e.rotation, e.translation});
      }
    }
    std::printf("%s hecal vs OpenCV, noise-free: %.2g (rad or m)\n", peer.name, worst);
    EXPECT_LT(worst, 1e-9) << peer.name;
  }
}

// With 0.3 mm / 0.3° noise the two differ (OpenCV's ANDREFF solves rotation and translation
// jointly and orthogonalises afterwards; hecal's solves them in two steps. OpenCV's DANIILIDIS
// uses canonical quaternion signs and no consistency check), so compare accuracy against the
// truth instead: hecal must be at least as accurate, within 10%.
TEST(DaniilidisAndreffOpenCvPeer, AtLeastAsAccurateOnNoisyBenignData) {
  for (const Peer& peer : kPeers) {
    const testing::PeerAccuracy accuracy = testing::ComparePeerAccuracy(
        [&peer](const Problem& problem, bool use_opencv) {
          const Pose X = use_opencv ? testing::OpenCvHandEye(problem, peer.opencv)
                                    : peer.hecal(AllPairMotions(problem));
          return Solution{X, Pose::Identity()};
        },
        40, /*check_z=*/false, peer.name);
    EXPECT_LE(accuracy.hecal_rotation_deg, 1.1 * accuracy.opencv_rotation_deg) << peer.name;
    EXPECT_LE(accuracy.hecal_translation, 1.1 * accuracy.opencv_translation) << peer.name;
  }
}

// Relative rotations of 170°–179.9°: OpenCV 4.6's DANIILIDIS takes both quaternions with w ≥ 0,
// which near π picks inconsistent signs, and fails; hecal's aligns the signs through a sign-free
// rotation estimate and stays exact. OpenCV's errors are printed, not asserted (they document
// the peer, not hecal).
TEST(DaniilidisAndreffOpenCvPeer, WideRotationsBreakOpenCvDaniilidisNotHecal) {
  double worst_hecal = 0.0, worst_opencv = 0.0;
  int opencv_failures = 0;
  for (handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    for (uint64_t seed = 1; seed <= 10; ++seed) {
      const testing::Scene data = testing::WideRotationCase(setup, 8, seed);
      const Problem problem = data.MeasuredProblem();
      const Pose X = SolveDaniilidis(AllPairMotions(problem));
      testing::ExpectPoseNear(X, data.X, 1e-9, "hecal daniilidis");
      worst_hecal = std::max(worst_hecal, Error(X, data.X).rotation);
      const Pose X_cv = testing::OpenCvHandEye(problem, cv::CALIB_HAND_EYE_DANIILIDIS);
      const double cv_error =
          X_cv.matrix().allFinite() ? Degrees(Error(X_cv, data.X).rotation) : 180.0;
      worst_opencv = std::max(worst_opencv, cv_error);
      if (cv_error > 1.0) ++opencv_failures;
    }
  }
  std::printf(
      "wide rotations (20 data sets), daniilidis: hecal worst %.2g rad; OpenCV worst %.1f deg, "
      "%d of 20 off by more than 1 deg\n",
      worst_hecal, worst_opencv, opencv_failures);
}

}  // namespace
}  // namespace hecal::handeye
