// The result files of `hecal contour track` (docs/contour.md, docs/cli.md): a tracked image
// sequence (contour/sequence.h) as CSV, one row per frame, or as JSON with full covariances.
//
// CSV: a '#' comment line (hecal version, units, rotation sequence), then the header
//   frame,image,status,edges_used,edges_searched,sigma_px,residual_rms_px,
//   tx,ty,m11m1,m22m1,m21,m12, sd_<each>, <the six pose parameters> (angles as <name>_deg),
//   sd_<each>, bias
// — S with tx, ty in px from the principal point; the pose in the unit of Z0 and degrees, its
// 1σ from the UT; the pose columns empty for a singular frame; bias lists the parameters the
// bias check flags (contour/pose_uncertainty.h), space-separated.
// JSON: {"hecal_version", "command": "contour track", "pose_model": "perspective"|"weak",
//   "units", "camera": {"focal_px", "z0", "principal_point"}, "subspace",
//   "rotation": {"form", "sequence"}, "shape_names", "pose_parameter_names", "template_shape",
//   "polarity", "frames": [{"frame", "image", "status", "edges": {"searched", "found", "used"},
//   "measurement_sigma_px", "measurement_sigma_source", "residual_rms_px", "shape",
//   "shape_covariance", "x", "x_covariance",
//   "pose": {"translation", "rotation_matrix", "euler_deg", "parameters", "covariance",
//            "ut_mean", "bias"} (not for a singular frame)}, ...]}
#pragma once

#include <string>
#include <vector>

#include "hecal/contour/sequence.h"
#include "hecal/geometry/types.h"

namespace hecal::report {

struct ContourTrack {
  contour::SequenceTrackingOptions options;    // the tracker's set-up
  Vector6d template_shape = Vector6d::Zero();  // ShapeTracker::template_shape()
  int polarity = 0;                            // ShapeTracker::polarity()
  std::vector<contour::TrackedImage> frames;
};

std::string ContourTrackCsv(const ContourTrack& track);
std::string ContourTrackJson(const ContourTrack& track);  // two-space indent, final newline

}  // namespace hecal::report
