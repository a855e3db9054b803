// `hecal contour pose|study|track|render` (docs/contour.md): camera motion from the affine
// deformation of a planar contour.
//
//   hecal contour pose --shape tx,ty,m11m1,m22m1,m21,m12 --z0 Z0 --focal F
//                      [--rotation zyx|zxz] [--json] [--covariance c11,...,c66 [--ut-w0 W]]
//     The motion of one shape vector S = (tx, ty, M11 − 1, M22 − 1, M21, M12) (the contour paper's
//     order; f and tx, ty share a unit, Z0 and the translation share a unit). --json prints
//     {"translation": [Tx,Ty,Tz], "rotation_matrix": [[…],[…],[…]], "euler": [a1,a2,a3],
//      "sequence": "ZYX"|"ZXZ", "units": {…}} with the Euler angles in radians
//     (docs/conventions.md) and also "euler_deg". With --covariance (36 numbers, row-major Σ_S, or
//     6 variances) the UT adds "covariance" (6×6 over Tx,Ty,Tz + the Euler angles),
//     "parameters", "ut_mean", "bias" (docs/contour.md#the-bias-check). The job is
//     contour/shape_pose.h, the JSON report/contour_pose_file.h.
//   hecal contour study --motion tx|ty|tz|rx|ry|rz --from A --to B --steps N … (contour_study.h)
//   hecal contour track / render: contour_track.cc.
// Errors: bad flags → InputError, a singular shape vector (det M ≤ 0: the plane edge-on or a
// reflection) → DegenerateError; both exit 2.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "cli.h"
#include "hecal/contour/affine_pose.h"

namespace hecal::cli {

// `count` comma-separated finite numbers from flag `flag` (InputError naming the flag
// otherwise). `what` describes them for the fix, e.g. "TX,TY,TZ,RX,RY,RZ".
std::vector<double> ParseNumberList(const std::string& flag, const std::string& text,
                                    std::size_t count, const std::string& what);

// One finite number (ParseNumberList with count 1).
double ParseNumber(const std::string& flag, const std::string& text, const std::string& what);
// The camera of the contour commands from --focal and --z0 (contour::ValidateContourCamera).
contour::ContourCamera ParseContourCamera(const std::string& focal, const std::string& z0);

// A contour file: CSV (or whitespace-separated) with the header `x,y` (case-insensitive; '#'
// comment lines), one point per line, at least 4 points. InputError with file:line otherwise.
Eigen::Matrix2Xd ReadContourFile(const std::string& path);

struct ContourPoseOptions {
  std::string shape;
  std::string z0;
  std::string focal;
  std::string rotation = "zyx";
  std::string covariance;  // "" = none
  std::string ut_w0 = "0";
  bool json = false;
};
void RunContourPose(const ContourPoseOptions& options, const Io& io);

// Subcommands of `contour` defined in their own files.
void AddContourStudyCommand(CLI::App& contour, const Io& io);
void AddContourTrackCommand(CLI::App& contour, const Io& io);
void AddContourRenderCommand(CLI::App& contour, const Io& io);

}  // namespace hecal::cli
