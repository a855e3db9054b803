// Camera pose from known points with OpenCV 4.6's solvePnP (docs/pose-from-points.md, the OpenCV
// side; the Eigen solvers are in hecal/pose). Given object points P_k in the target frame and their
// pixels (u_k, v_k) in a camera with the plumb_bob model of pose/camera_model.h, returns
//   T_camera_target = [R | t],  R = Rodrigues(rvec), t = tvec  (solvePnP's outputs),
// so x_camera = T_camera_target · P_k. Lengths: the object points' unit (metres in hecal), and
// t comes out in the same unit; pixels as OpenCV (origin at the centre of the top-left pixel).
//
// Methods (`hecal pose --method NAME`):
//   ippe       SOLVEPNP_IPPE — Collins & Bartoli, "Infinitesimal Plane-Based Pose Estimation",
//              IJCV 109(3), 2014. Coplanar points only (any plane), n ≥ 4; of its two
//              solutions OpenCV returns the one with the smaller reprojection error.
//   sqpnp      SOLVEPNP_SQPNP — Terzakis & Lourakis, "A Consistently Fast and Globally Optimal
//              Solution to the Perspective-n-Point Problem", ECCV 2020. n ≥ 3, planar or not.
//   epnp       SOLVEPNP_EPNP — Lepetit, Moreno-Noguer & Fua, "EPnP: An Accurate O(n) Solution
//              to the PnP Problem", IJCV 81(2), 2009. n ≥ 4.
//   iterative  SOLVEPNP_ITERATIVE — Levenberg–Marquardt on the reprojection error, started from
//              a homography (coplanar points, n ≥ 4) or from a DLT (n ≥ 6 otherwise), or from
//              `initial` when given (n ≥ 4).
//
// Preconditions, checked (hecal::InputError; source "PnpMethod NAME", "object points" or "camera"):
// as many pixels as object points; every value finite; the method's minimum n; for ippe, coplanar
// object points (largest distance from their least-squares plane ≤ 1e-6 × the points' extent; the
// error says how far off and which methods accept non-planar points); fx, fy > 0. Degenerate data
// throw hecal::DegenerateError: all object points (nearly) on one line, or OpenCV failing /
// returning a non-finite pose. Points behind the camera are not checked (OpenCV does not either);
// the returned pose is whatever the method converged to.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "hecal/geometry/types.h"
#include "hecal/pose/camera_model.h"

namespace hecal::vision {

enum class PnpMethod { kIppe, kSqpnp, kEpnp, kIterative };

struct PnpMethodInfo {
  PnpMethod method;
  std::string_view name;     // CLI name, e.g. "ippe"
  std::string_view summary;  // one line: what it is, when to use it
  int min_points;            // smallest n OpenCV accepts for this method (general position)
  bool planar_only;          // true for ippe
};

// Every method, in the order `hecal pose --help` lists them.
std::span<const PnpMethodInfo> OpenCvPnpMethods();
const PnpMethodInfo& Info(PnpMethod method);
std::optional<PnpMethod> ParsePnpMethod(std::string_view name);

// T_camera_target from object points (target frame) and their pixels, with OpenCV's `method`.
// `initial` (iterative only; ignored by the closed-form methods, which take no guess) starts
// Levenberg–Marquardt from that pose instead of the homography / DLT.
Pose SolvePnPOpenCv(PnpMethod method, const std::vector<Eigen::Vector3d>& object_points,
                    const std::vector<Eigen::Vector2d>& pixels, const pose::CameraModel& camera,
                    const std::optional<Pose>& initial = std::nullopt);

// The pose hecal uses for image stations: for coplanar object points, IPPE followed by
// SOLVEPNP_ITERATIVE started from it (IPPE's closed form is not the maximum-likelihood pose
// under pixel noise; the iteration makes it so); for non-planar points, SQPnP then ITERATIVE.
Pose SolvePnPOpenCvRefined(const std::vector<Eigen::Vector3d>& object_points,
                           const std::vector<Eigen::Vector2d>& pixels,
                           const pose::CameraModel& camera);

// True when the points lie on one plane within 1e-6 × their extent (the ippe precondition).
bool AreCoplanar(const std::vector<Eigen::Vector3d>& points);

}  // namespace hecal::vision
