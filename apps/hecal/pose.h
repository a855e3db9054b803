// `hecal pose --points object.csv --image-points image.csv (--focal F | --intrinsics camera.yaml)
//             [--principal-point CX,CY] [--method NAME] [--pixel-sigma PX] [--units m|mm]
//             [--output pose.json]`                                        (docs/cli.md)
// Camera pose T_camera_target from known object points and their pixels (docs/pose-from-points.md).
//
// Inputs
//   object.csv  header `id,x,y,z` (id optional; case-insensitive; '#' comment lines; commas, or
//               whitespace when the header has no comma). Lengths: a suffix on all three
//               (x_mm,y_mm,z_mm or _m) wins over --units (default m).
//   image.csv   header `id,u,v` (id optional), pixels with the origin at the centre of the
//               top-left pixel (OpenCV's convention).
//   Pairing: by id when both files have ids (every image id must name an object point; object
//   points without an image point are left out), otherwise by order (equal counts).
//   Camera: --intrinsics camera.yaml (io/camera_file.h: hecal, OpenCV or ROS layout, plumb_bob
//   distortion), or --focal F (px) for the linear pose paper's distortion-free pinhole X = F x/z
//   with the principal point at --principal-point (default 0,0: image coordinates measured from
//   it).
// Methods: linear (default) | linear-raw | dlt (pose/pose_method.h); with the vision layer also
//   OpenCV's ippe | sqpnp | epnp (as OpenCV returns them) and iterative (OpenCV's
//   Levenberg–Marquardt, then hecal's refinement, which adds the covariance at that minimum).
// Output: R, t (the object file's unit), the rotation vector, the 1σ of each component (refined
//   methods), the RMS reprojection error sqrt(Σ‖e_k‖²/N) (px per point, as OpenCV reports it)
//   and σ per axis (given by --pixel-sigma, or estimated from the residuals; ≈ RMS/√2).
//   --output writes JSON atomically (report/pose_file.h):
//   {"hecal_version", "method", "units": {"length", "angle"},
//    "T_camera_target": {"frame", "matrix", "translation", "quaternion_wxyz", "rotation_vector"},
//    "covariance": {"matrix" (6×6), "parameterization": "right, (rx,ry,rz,tx,ty,tz)",
//                   "pixel_sigma", "pixel_sigma_source": "given"|"estimated"}   (refined only)
//    "reprojection_rms_px", "points": [{"id", "residual_px": [du, dv]}, ...], "warnings": [...]}
//   Warnings (e.g. an unreliable linear-pose estimate, pose_method.h) also go to stderr.
// The flags bind into report::PointPoseOptions (report/point_pose.h: reading, pairing, the
//   camera and the solve); its IsValid names fields, mapped to flags here (field_flags.h).
// Errors: InputError with file:line for bad files (exit 2), DegenerateError when the method cannot
//   determine the pose from these points (exit 2, with the methods that can); nothing is written.
#pragma once

#include "cli.h"

// RegisterPoseCommand (cli.h) adds the subcommand.
