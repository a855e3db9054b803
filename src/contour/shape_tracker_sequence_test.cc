// The shape-space tracker on a rendered sequence with known motion (the contour paper's setting: Z0
// = 5000 mm, f = 50 mm with 8.3 µm pixels, i.e. f ≈ 6024 px; the 12-point irregular target of
// contour_study.h, ~250 × 180 mm): is the covariance it reports honest?
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "hecal/contour/affine_pose.h"
#include "hecal/contour/contour_study.h"
#include "hecal/contour/perspective_pose.h"
#include "hecal/contour/perspective_view.h"
#include "hecal/contour/pose_uncertainty.h"
#include "hecal/contour/render.h"
#include "hecal/contour/shape_space.h"
#include "hecal/contour/shape_tracker.h"
#include "hecal/geometry/angle_units.h"

namespace hecal::contour {
namespace {

// Six numbers; with `pose`, the last three (radians) in degrees.
std::string Format(const Vector6d& v, bool pose) {
  char text[160];
  std::snprintf(text, sizeof text, "%.4g %.4g %.4g %.4g %.4g %.4g", v(0), v(1), v(2),
                pose ? v(3) / kRadiansPerDegree : v(3), pose ? v(4) / kRadiansPerDegree : v(4),
                pose ? v(5) / kRadiansPerDegree : v(5));
  return text;
}

// The affinity a perfect tracker converges to on a non-affine (perspective) image: the
// least-squares fit of the normal distances from the affine curve's sample points (the tracker's
// points_per_span) to the true outline `outline` (a dense polygon), iterated to convergence —
// geometry only, no image. Everything is relative to the principal point.
Vector6d NormalFitReference(const ShapeSpace& space, const Eigen::Matrix2Xd& outline,
                            int points_per_span, Vector6d start) {
  Eigen::VectorXd x = space.Reduce(start);
  const Eigen::Index n = space.template_points().cols();
  for (int iteration = 0; iteration < 8; ++iteration) {
    const ClosedBSpline curve(space.Apply(x));
    const Eigen::VectorXd s = curve.SampleParameters(points_per_span);
    Eigen::MatrixXd H(s.size(), space.dim());
    Eigen::VectorXd y(s.size());
    for (Eigen::Index j = 0; j < s.size(); ++j) {
      const Eigen::Vector2d r = curve.Point(s(j)), normal = curve.Normal(s(j));
      double best = std::numeric_limits<double>::infinity();
      for (Eigen::Index i = 0; i < outline.cols(); ++i) {
        const Eigen::Vector2d a = outline.col(i), b = outline.col((i + 1) % outline.cols());
        Eigen::Matrix2d M;
        M << normal, a - b;  // r + t n = a + u (b − a)
        if (std::abs(M.determinant()) < 1e-12) continue;
        const Eigen::Vector2d tu = M.partialPivLu().solve(a - r);
        if (tu(1) >= 0.0 && tu(1) < 1.0 && std::abs(tu(0)) < std::abs(best)) best = tu(0);
      }
      const Eigen::RowVectorXd basis = curve.Basis(s(j));
      H.row(j) = normal.x() * (basis * space.W().topRows(n)) +
                 normal.y() * (basis * space.W().bottomRows(n));
      y(j) = H.row(j).dot(x) + best;
    }
    x = (H.transpose() * H).ldlt().solve(H.transpose() * y);
  }
  return space.Shape(x);
}

struct SequenceFrame {
  Eigen::Matrix3d rotation;
  Eigen::Vector3d translation;
  double tilt = 0.0;  // angle between the plane normal and the optical axis (rad)
  TrackedFrame tracked;
  Vector6d truth_shape;   // ShapeFromPose (weak perspective about the target origin)
  Vector6d affine_shape;  // the affinity of the rendered outline (the model's truth): the
                          // truth on weak-perspective images, else NormalFitReference
};

struct Sequence {
  ContourCamera camera{50.0 / 0.0083, 5000.0};
  Eigen::Vector2d principal_point{384.3, 288.6};
  int width = 768, height = 576;
  std::vector<SequenceFrame> frames;
};

// 30 frames: approach 900 mm, lateral (60, −40) mm, tilt Rx to 20° and Ry to 12°, Rz to 25°;
// pixel noise 3 grey levels on a contrast of 120, quantised to 8 bits.
// perspective: the true pinhole image (render.h); otherwise the weak-perspective image, the
// affinity ShapeFromPose applied to the template, for which the model is exact.
Sequence RunSequence(bool perspective, std::uint64_t seed) {
  constexpr int frames = 30;
  const ShapeTrackerOptions options;
  Sequence sequence;
  const ClosedBSpline target(DefaultTarget());
  const ShapeSpace space(TemplateImage(target.control_points(), sequence.camera));
  RenderOptions render;
  render.noise_sigma = 3.0;
  render.quantize = true;
  const Eigen::Matrix2Xd init =
      TemplateImage(target.control_points(), sequence.camera).colwise() + sequence.principal_point;
  ShapeTracker tracker(init, sequence.principal_point, options);
  for (int t = 0; t < frames; ++t) {
    const double u = frames > 1 ? static_cast<double>(t) / (frames - 1) : 0.0;
    SequenceFrame frame;
    frame.translation = u * Eigen::Vector3d(60.0, -40.0, -900.0);
    frame.rotation = RotationZyx(u * 20.0 * kRadiansPerDegree, u * 12.0 * kRadiansPerDegree,
                                 u * 25.0 * kRadiansPerDegree);
    frame.tilt = std::acos(std::clamp(frame.rotation(2, 2), -1.0, 1.0));
    render.seed = seed * 1000 + static_cast<std::uint64_t>(t);
    frame.truth_shape = ShapeFromPose(frame.rotation, frame.translation, sequence.camera);
    Eigen::Matrix2Xd outline;
    if (perspective) {
      outline = PerspectiveOutline(target, frame.rotation, frame.translation, sequence.camera,
                                   sequence.principal_point, 64);
    } else {
      outline =
          (AffinityMatrix(frame.truth_shape) * TemplateImage(target.Sample(64), sequence.camera))
              .colwise() +
          (AffinityTranslation(frame.truth_shape) + sequence.principal_point);
    }
    frame.tracked = tracker.Track(RenderPolygon(outline, sequence.width, sequence.height, render));
    frame.affine_shape =
        perspective ? NormalFitReference(space, outline.colwise() - sequence.principal_point,
                                         options.points_per_span, frame.truth_shape)
                    : frame.truth_shape;
    sequence.frames.push_back(std::move(frame));
  }
  return sequence;
}

// The sequence of (perspective, seed), run once for all the tests below (rendering, tracking and
// the reference fit are most of their time).
const Sequence& SharedSequence(bool perspective, std::uint64_t seed = 1) {
  static std::map<std::pair<bool, std::uint64_t>, Sequence> sequences;
  const std::pair<bool, std::uint64_t> key(perspective, seed);
  auto found = sequences.find(key);
  if (found == sequences.end())
    found = sequences.emplace(key, RunSequence(perspective, seed)).first;
  return found->second;
}

Vector6d Normalised(const Vector6d& error, const Matrix6d& covariance) {
  return error.cwiseQuotient(covariance.diagonal().cwiseSqrt());
}

// Counts of normalised errors |z| ≤ 3 and the largest |z|.
struct Coverage {
  int within = 0;
  int total = 0;
  double worst = 0.0;
  void Add(double z) {
    ++total;
    if (std::abs(z) <= 3.0) ++within;
    worst = std::max(worst, std::abs(z));
  }
  double fraction() const { return total > 0 ? static_cast<double>(within) / total : 0.0; }
};

struct SequenceCheck {
  Coverage shape_vs_truth, shape_vs_reference, pose_vs_truth;
  std::array<Coverage, 6> pose_component;
  double shape_nees = 0.0;  // mean over frames of e_Sᵀ Σ_S⁻¹ e_S against the truth (6 dof)
  Vector6d last_shape_error, last_pose_error, last_pose_sd;  // last frame, vs the truth
};

// The checks of both tests: S against ShapeFromPose (truth) and against the normal-fit reference,
// and the pose of PoseFromShape against CanonicalPose within the UT covariance, leaving out Rx and
// Ry while the true tilt is below 10° (docs/contour.md#the-bias-check: there their sign is not
// observable and the UT is biased).
SequenceCheck Check(const Sequence& sequence) {
  SequenceCheck check;
  int frames = 0;
  for (const SequenceFrame& f : sequence.frames) {
    const TrackedFrame& r = f.tracked;
    EXPECT_TRUE(r.updated) << r.frame;
    EXPECT_GE(r.edges_used, 90) << r.frame;  // of 96
    if (r.frame == 0) {                      // the template view: S = 0 by definition, exactly
      EXPECT_EQ(r.shape, Vector6d::Zero());
      continue;
    }
    const Vector6d z_truth = Normalised(r.shape - f.truth_shape, r.shape_covariance);
    const Vector6d z_reference = Normalised(r.shape - f.affine_shape, r.shape_covariance);
    const Vector6d e = r.shape - f.truth_shape;
    check.shape_nees += e.dot(r.shape_covariance.ldlt().solve(e));
    ++frames;
    const ContourPoseUncertainty pose =
        UnscentedPose(r.shape, r.shape_covariance, sequence.camera, RotationForm::kZyx);
    const Vector6d truth =
        PoseParameters(CanonicalPose(f.rotation, f.translation, RotationForm::kZyx));
    const Vector6d pose_error = PoseDifference(pose.parameters, truth, RotationForm::kZyx);
    const Vector6d z_pose = Normalised(pose_error, pose.covariance);
    for (int i = 0; i < 6; ++i) {
      check.shape_vs_truth.Add(z_truth(i));
      check.shape_vs_reference.Add(z_reference(i));
      const bool tilt_component = i == 3 || i == 4;
      if (tilt_component && f.tilt < 10.0 * kRadiansPerDegree) continue;
      check.pose_vs_truth.Add(z_pose(i));
      check.pose_component[static_cast<std::size_t>(i)].Add(z_pose(i));
    }
    check.last_shape_error = e;
    check.last_pose_error = pose_error;
    check.last_pose_sd = pose.covariance.diagonal().cwiseSqrt();
  }
  check.shape_nees /= std::max(1, frames);
  const auto& c = check;
  std::printf("S vs truth: %d/%d within 3σ, worst %.1fσ, mean NEES %.2f (6 dof)\n",
              c.shape_vs_truth.within, c.shape_vs_truth.total, c.shape_vs_truth.worst,
              c.shape_nees);
  std::printf("S vs normal-fit reference: %d/%d within 3σ, worst %.1fσ\n",
              c.shape_vs_reference.within, c.shape_vs_reference.total, c.shape_vs_reference.worst);
  std::printf("pose vs truth (UT): %d/%d within 3σ; per component worst |z| (Tx Ty Tz Rx Ry Rz):",
              c.pose_vs_truth.within, c.pose_vs_truth.total);
  for (const Coverage& p : c.pose_component) std::printf(" %.1f", p.worst);
  std::printf(
      "\nlast frame: S error (px, px, -, -, -, -) %s\n  pose error (mm, °) %s\n  pose σ %s\n",
      Format(c.last_shape_error, false).c_str(), Format(c.last_pose_error, true).c_str(),
      Format(c.last_pose_sd, true).c_str());
  return check;
}

// The tracker on weak-perspective images (the affine model exact): the covariance must be honest
// for S and, through the UT, for the pose.
TEST(ShapeTrackerSequence, CovarianceIsHonestWhenTheAffineModelHolds) {
  const Sequence& sequence = SharedSequence(/*perspective=*/false);
  const SequenceCheck check = Check(sequence);
  EXPECT_GE(check.shape_vs_truth.fraction(), 0.95);  // measured 172/174
  EXPECT_LT(check.shape_vs_truth.worst, 4.5);        // measured 3.2
  EXPECT_GT(check.shape_nees, 6.0 / 3.0);            // neither overconfident …
  EXPECT_LT(check.shape_nees, 6.0 * 2.0);            // … nor uselessly pessimistic
  EXPECT_GE(check.pose_vs_truth.fraction(), 0.95);   // measured 150/150
  EXPECT_LT(check.pose_vs_truth.worst, 4.5);
}

// On true perspective images the tracker is still honest about what it measures — the affinity
// that best fits the image (NormalFitReference) — but that affinity is not weak perspective's
// ShapeFromPose of the motion: with the paper's target (≈ 250 × 180 mm at 5 m) the perspective
// term f·sin(tilt)·X²/Z0² reaches ~0.8 px at the target's edge at 20° of tilt, and shifts the
// fitted translation by about f·sin(tilt)·mean(X²)/Z0², tens of the tracker's σ. This test pins
// both facts down (figures in the report printed above).
TEST(ShapeTrackerSequence, PerspectiveImagesShowTheWeakPerspectiveModelError) {
  const Sequence& sequence = SharedSequence(/*perspective=*/true);
  const SequenceCheck check = Check(sequence);
  EXPECT_GE(check.shape_vs_reference.fraction(), 0.95);
  EXPECT_LT(check.shape_vs_reference.worst, 4.5);
  // The model error: S against the truth is far outside the tracker's precision (measured: 73
  // of 174 within 3σ, worst 64σ, tx 0.96 px off at the last frame), and so is the pose (Tx 0.61
  // mm off with σ 0.019 mm, worst 36σ; Rx worst 15σ; Tz and Rz about 90% and 80% within 3σ).
  EXPECT_LT(check.shape_vs_truth.fraction(), 0.8);
  EXPECT_GT(check.shape_vs_truth.worst, 20.0);
  EXPECT_GT(check.pose_component[0].worst, 10.0);       // Tx
  EXPECT_GT(std::abs(check.last_shape_error(0)), 0.5);  // px
}

// The same perspective images with the perspective pose (perspective_pose.h): the weak-
// perspective bias is removed, and the motion is recovered within the precision the tracker's own
// covariance predicts (UT through the perspective pose), as on affine images.
TEST(ShapeTrackerSequence, PerspectivePoseRecoversTheMotionWithinItsCovariance) {
  const Sequence& sequence = SharedSequence(/*perspective=*/true);
  const PerspectivePoseModel model(TemplateImage(DefaultTarget(), sequence.camera),
                                   sequence.camera);
  const PoseOfShape pose_of = [&](const Vector6d& s) { return model.Pose(s, RotationForm::kZyx); };
  Coverage all;
  std::array<Coverage, 6> component;
  for (const SequenceFrame& f : sequence.frames) {
    if (f.tracked.frame == 0) continue;
    const ContourPoseUncertainty pose =
        UnscentedPose(f.tracked.shape, f.tracked.shape_covariance, pose_of, RotationForm::kZyx);
    const Vector6d truth =
        PoseParameters(CanonicalPose(f.rotation, f.translation, RotationForm::kZyx));
    const Vector6d z =
        Normalised(PoseDifference(pose.parameters, truth, RotationForm::kZyx), pose.covariance);
    for (int i = 0; i < 6; ++i) {
      if ((i == 3 || i == 4) && f.tilt < 10.0 * kRadiansPerDegree) continue;
      all.Add(z(i));
      component[static_cast<std::size_t>(i)].Add(z(i));
    }
  }
  std::printf("perspective pose vs truth (UT): %d/%d within 3σ; worst |z| (Tx Ty Tz Rx Ry Rz):",
              all.within, all.total);
  for (const Coverage& c : component) std::printf(" %.1f", c.worst);
  std::printf("\n");
  EXPECT_GE(all.fraction(), 0.95);
  EXPECT_LT(all.worst, 4.5);
}

// The study behind the figures in the report (10 noise seeds of the weak-perspective sequence,
// run once, shared): per-component coverage of S and of the pose within 3σ, and the mean NEES of S.
TEST(ShapeTrackerSequence, ManySeedsStudy) {
  std::array<Coverage, 6> shape, pose;
  double nees = 0.0;
  int sequences = 0;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const Sequence& sequence = SharedSequence(/*perspective=*/false, seed);
    const SequenceCheck check = Check(sequence);
    nees += check.shape_nees;
    ++sequences;
    for (const SequenceFrame& f : sequence.frames) {
      const TrackedFrame& r = f.tracked;
      if (r.frame == 0) continue;
      const Vector6d z = Normalised(r.shape - f.truth_shape, r.shape_covariance);
      const ContourPoseUncertainty u =
          UnscentedPose(r.shape, r.shape_covariance, sequence.camera, RotationForm::kZyx);
      const Vector6d truth =
          PoseParameters(CanonicalPose(f.rotation, f.translation, RotationForm::kZyx));
      const Vector6d zp =
          Normalised(PoseDifference(u.parameters, truth, RotationForm::kZyx), u.covariance);
      for (std::size_t i = 0; i < 6; ++i) {
        shape[i].Add(z(static_cast<int>(i)));
        if ((i == 3 || i == 4) && f.tilt < 10.0 * kRadiansPerDegree) continue;
        pose[i].Add(zp(static_cast<int>(i)));
      }
    }
  }
  std::printf("mean NEES of S over %d sequences: %.2f (6 dof)\n", sequences, nees / sequences);
  for (std::size_t i = 0; i < 6; ++i) {
    std::printf("component %zu: S %.3f within 3σ (worst %.1f), pose %.3f (worst %.1f)\n", i,
                shape[i].fraction(), shape[i].worst, pose[i].fraction(), pose[i].worst);
    EXPECT_GE(shape[i].fraction(), 0.9);
    EXPECT_GE(pose[i].fraction(), 0.9);
  }
}

}  // namespace
}  // namespace hecal::contour
