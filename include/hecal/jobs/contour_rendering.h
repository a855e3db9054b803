// A synthetic image sequence of a planar contour target under a known motion as one job (`hecal
// contour render`; docs/contour.md, docs/cli.md#hecal-contour-render), writing nothing: every
// frame goes to the caller as PNG bytes as soon as it is rendered, and the text files that go
// beside the frames come back in the result (a folder written all or none: io/atomic_file.h,
// StagedFolder).
//
// Steps (RenderContourSequence)
//   1. The options checked (IsValid) before any file is read.
//   2. The target: the points of the contour file (io/contour_file.h, in the target plane, Z0's
//      unit) when one is given, else the options' target, else the built-in one
//      (contour/contour_study.h, DefaultTarget).
//   3. contour::RenderSequence (contour/sequence.h): the motion interpolated linearly from `from`
//      to `to`, a true pinhole with the principal point at the image centre, area coverage, blur
//      and pixel noise, 8-bit; each frame encoded as PNG (vision/contour_images.h) and handed to
//      `on_frame` with its file name (report/contour_render_file.h: frame_0000.png, ...).
//   4. init.csv (the first view's control points in pixels, the input of contour tracking) and
//      truth.csv (the motion and its weak-perspective shape vector per frame), as
//      report/contour_render_file.h writes them.
// The result counts the frames where the target leaves the image (the tracker cannot follow it
// there); the caller decides how to say so.
// Frames and units: motion Tx, Ty, Tz in Z0's unit and Rx, Ry, Rz in degrees, x_camera = R p +
// (Tx, Ty, Z0 + Tz), R = Rz Ry Rx; image coordinates in pixels.
//
// Errors (hecal::InputError): invalid options (source the field: ContourCamera.*,
// SequenceRenderOptions.*, RenderOptions.*); those of the contour file and of PNG encoding, and
// what `on_frame` throws, pass through (hecal::DegenerateError for a collinear target).
#pragma once

#include <functional>
#include <string>

#include "hecal/contour/sequence.h"

namespace hecal::jobs {

struct ContourRenderingOptions {
  // Camera, frames, motion, image size, noise, blur, seed; its target is used when `contour` is
  // empty (empty too: the built-in target).
  contour::SequenceRenderOptions sequence;
  std::string contour;  // a contour file of the target's control points ("" = none)

  // core/options_check.h: SequenceRenderOptions::IsValid of the sequence as it will be rendered
  // (the target of a contour file is checked when it is read).
  bool IsValid(std::string* why) const;
};

struct ContourRendering {
  contour::SequenceRenderOptions options;  // as rendered, with the target used
  contour::RenderedSequence rendered;      // per frame: motion, shape vector, outside the image
  std::string init_csv;                    // the file init.csv
  std::string truth_csv;                   // the file truth.csv
};

// Steps 1–4 above; `on_frame` (may be empty) receives each frame's file name and PNG bytes.
ContourRendering RenderContourSequence(
    const ContourRenderingOptions& options,
    const std::function<void(const std::string& name, const std::string& png)>& on_frame);

}  // namespace hecal::jobs
