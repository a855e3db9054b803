// `hecal contour pose|study|track|render` (docs/cli.md#hecal-contour-pose and the sections after
// it, docs/contour.md): camera motion from the affine deformation of a planar contour. `contour
// pose` (contour.cc) runs contour/shape_pose.h and prints report/contour_pose_file.h's JSON;
// study: contour_study_command.cc; track and render: contour_track.cc.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "bounds.h"
#include "cli.h"
#include "hecal/contour/affine_pose.h"

namespace hecal::cli {

// The camera of the contour commands from --focal and --z0 (contour::ValidateContourCamera).
contour::ContourCamera ParseContourCamera(const std::string& focal, const std::string& z0);

// --rotation of `contour pose` and `contour track`: zyx or zxz (InputError naming the flag).
contour::RotationForm ParseRotationFlag(const std::string& text);

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
