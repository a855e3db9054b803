// The uncertainty of the camera motion recovered from a contour
// (docs/contour.md#uncertainty-of-the-motion; the contour paper §IV): the shape vector S ~ (S̄,
// Σ_S) (from the Kalman tracker, or σ²(WᵀW)⁻¹ for a fit of noisy control points) is propagated
// through PoseFromShape to the six pose parameters (Tx, Ty, Tz and the Euler angles of the rotation
// form, PoseParameters order):
//  - UnscentedPose: the Unscented Transform with the contour paper's symmetric set, 2·6 + 1 = 13
//    sigma points (uncertainty/unscented.h). Default centre weight w0 = 0: the twelve outer points
//    at ±√6 σ along the Cholesky columns carry the weight, 1/12 each. The paper leaves w0 free;
//    the general default of unscented.h, 1 − n/3 = −1 (points at ±√3 σ, covariance about f(S̄)),
//    matches Monte Carlo as well (within 3%) once the tilt is 10° or more, but at zero tilt —
//    where λ1 of M Mᵀ has a kink, so Tz, Rx and Ry are not differentiable — it reports the
//    squared bias as variance: σ(Tz) 44% above Monte Carlo, against 10% with w0 = 0 (measured
//    on the default study: tx = 250 mm, rx = 0…40°);
//  - MonteCarloPose: the same input distribution sampled (default 5000 samples).
// Angles with a full-circle range (Rz; φ and ψ of zxz) are unwrapped to within π of f(S̄)
// before any average, so a distribution straddling 0 / 2π is not torn apart.
//
// The bias check (docs/contour.md#the-bias-check). With Rx, Ry restricted to one Necker member, a
// pair of mirrored sigma points near zero tilt map to the same sign: the UT mean then departs from
// the pose of the mean shape f(S̄), which is unbiased there. hecal flags parameter j as biased when
//   |ȳ_j − f(S̄)_j| > bias_threshold · σ_j        (σ_j the UT standard deviation; default 0.25)
// — for a smooth f the difference is second order (a small fraction of σ), while the fold gives
// about 0.8 σ. The paper reports the two coinciding everywhere except near zero Rx/Ry.
#pragma once

#include <Eigen/Core>
#include <array>
#include <functional>
#include <vector>

#include "hecal/contour/affine_pose.h"
#include "hecal/geometry/types.h"
#include "hecal/uncertainty/monte_carlo.h"
#include "hecal/uncertainty/unscented.h"

namespace hecal::contour {

struct ContourPoseUncertainty {
  ContourPose pose;              // the pose of the mean shape, f(S̄)
  Vector6d parameters;           // PoseParameters(pose)
  Vector6d mean;                 // the UT mean (circular angles near `parameters`)
  Matrix6d covariance;           // the UT covariance
  std::array<bool, 6> biased{};  // the bias check above, per parameter
  bool any_biased = false;
  // The sigma points and their poses (for plots): S_i and PoseParameters(f(S_i)).
  std::vector<Vector6d> sigma_shapes;
  std::vector<Vector6d> sigma_poses;
};

struct UnscentedPoseOptions {
  uncertainty::UnscentedParameters unscented = uncertainty::UnscentedParameters::Symmetric(0.0);
  double bias_threshold = 0.25;  // |mean − f(S̄)| / σ above which a parameter is biased (> 0)

  // core/options_check.h: false naming UnscentedPoseOptions.unscented (not valid for the 6
  // shape parameters, uncertainty/unscented.h) or .bias_threshold (not above 0 and finite).
  bool IsValid(std::string* why) const;
};

// The map from a shape vector to a pose: PoseFromShape (weak perspective, the contour paper's), or
// PerspectivePose (perspective_pose.h).
using PoseOfShape = std::function<ContourPose(const Vector6d&)>;

// Throws hecal::InputError when !options.IsValid, hecal::DegenerateError when f(S̄) or a sigma
// point is singular (affine_pose.h), and std::invalid_argument for an invalid covariance. The first
// form uses PoseFromShape.
ContourPoseUncertainty UnscentedPose(const Vector6d& shape, const Matrix6d& shape_covariance,
                                     const ContourCamera& camera, RotationForm form,
                                     const UnscentedPoseOptions& options = {});
ContourPoseUncertainty UnscentedPose(const Vector6d& shape, const Matrix6d& shape_covariance,
                                     const PoseOfShape& pose_of_shape, RotationForm form,
                                     const UnscentedPoseOptions& options = {});

// Pose parameters of a shape vector with the circular angles unwrapped to within π of
// `reference` (a PoseParameters vector of the same form).
Vector6d PoseParametersNear(const Vector6d& shape, const ContourCamera& camera, RotationForm form,
                            const Vector6d& reference);
Vector6d PoseParametersNear(const Vector6d& shape, const PoseOfShape& pose_of_shape,
                            RotationForm form, const Vector6d& reference);
// a − b with circular angles wrapped into (−π, π].
Vector6d PoseDifference(const Vector6d& a, const Vector6d& b, RotationForm form);

// Monte Carlo over S ~ N(S̄, Σ_S). Samples whose pose is singular are counted as failures.
uncertainty::MonteCarloMoments<Eigen::VectorXd> MonteCarloPose(
    const Vector6d& shape, const Matrix6d& shape_covariance, const ContourCamera& camera,
    RotationForm form, const uncertainty::MonteCarloOptions& options = {});

}  // namespace hecal::contour
