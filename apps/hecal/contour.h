// `hecal contour pose|study|track|render` (docs/cli.md#hecal-contour-pose and the sections after
// it, docs/contour.md): camera motion from the affine deformation of a planar contour. `contour
// pose` (contour.cc) binds contour::ShapePoseOptions (contour/shape_pose.h) and prints
// report/contour_pose_file.h's JSON or report/contour_pose_text.h's text; study:
// contour_study_command.cc; track and render: contour_track.cc (jobs/contour_tracking.h,
// jobs/contour_rendering.h).
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "cli.h"
#include "hecal/hecal.h"

namespace hecal::cli {

// --rotation of `contour pose` and `contour track`: zyx or zxz, a choice (choice_flags.h).
CLI::Option* AddRotationFlag(CLI::App& command, contour::RotationForm& form);

// Subcommands of `contour` defined in their own files.
void AddContourStudyCommand(CLI::App& contour, const Io& io);
void AddContourTrackCommand(CLI::App& contour, const Io& io);
void AddContourRenderCommand(CLI::App& contour, const Io& io);

}  // namespace hecal::cli
