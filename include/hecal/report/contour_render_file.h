// The text files of `hecal contour render` (docs/contour.md, docs/cli.md) beside the frames of
// a rendered sequence (contour/sequence.h), and the frames' file names.
//
// truth.csv: a '#' comment line (hecal version, the motion model x_camera = R p + (Tx, Ty,
//   Z0 + Tz) with R = Rz Ry Rx, Z0, f in px, the principal point, the noise seed), then the
//   header frame,image,Tx,Ty,Tz,Rx_deg,Ry_deg,Rz_deg,tx,ty,m11m1,m22m1,m21,m12 and one row per
//   frame: the motion (Z0's unit, degrees) and the weak-perspective shape vector S of it
//   (tx, ty in px from the principal point; contour/shape_space.h).
// init.csv: a '#' comment line, the header x,y and the control points of the first view in
//   pixels (origin at the centre of the top-left pixel), the input of `contour track --init`.
// Numbers are written shortest round-trip (io/delimited_text.h).
#pragma once

#include <string>

#include "hecal/contour/sequence.h"

namespace hecal::report {

// "frame_0000.png" for frame 0: the name of a rendered frame's image file.
std::string RenderedFrameName(int frame);

std::string RenderTruthCsv(const contour::SequenceRenderOptions& options,
                           const contour::RenderedSequence& rendered);
std::string RenderInitCsv(const contour::RenderedSequence& rendered);

}  // namespace hecal::report
