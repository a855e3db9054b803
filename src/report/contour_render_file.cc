// The text files of `hecal contour render`: see contour_render_file.h.
#include "hecal/report/contour_render_file.h"

#include <cstdio>

#include "hecal/io/delimited_text.h"
#include "hecal/version.h"

namespace hecal::report {

std::string RenderedFrameName(int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%04d.png", frame);
  return name;
}

std::string RenderTruthCsv(const contour::SequenceRenderOptions& options,
                           const contour::RenderedSequence& rendered) {
  std::string truth =
      "# hecal " + std::string(kVersion) +
      " contour render: x_camera = R p + (Tx, Ty, Z0 + Tz), R = Rz(Rz) Ry(Ry) Rx(Rx); Z0 = " +
      io::FormatDouble(options.camera.z0) + ", f = " + io::FormatDouble(options.camera.focal) +
      " px, principal point " + io::FormatDouble(rendered.principal.x()) + "," +
      io::FormatDouble(rendered.principal.y()) +
      "; tx..m12: the weak-perspective shape vector of the motion (tx, ty in px); noise seed " +
      std::to_string(options.seed) +
      "\n"
      "frame,image,Tx,Ty,Tz,Rx_deg,Ry_deg,Rz_deg,tx,ty,m11m1,m22m1,m21,m12\n";
  for (const contour::RenderedFrame& frame : rendered.frames) {
    truth += std::to_string(frame.index) + "," + RenderedFrameName(frame.index);
    for (int i = 0; i < 6; ++i) {
      truth += ",";
      io::AppendDouble(frame.motion(i), &truth);
    }
    for (int i = 0; i < 6; ++i) {
      truth += ",";
      io::AppendDouble(frame.shape(i), &truth);
    }
    truth += "\n";
  }
  return truth;
}

std::string RenderInitCsv(const contour::RenderedSequence& rendered) {
  std::string init = "# hecal contour render: control points of the first view (px)\nx,y\n";
  for (Eigen::Index i = 0; i < rendered.first_view.cols(); ++i) {
    io::AppendDouble(rendered.first_view(0, i), &init);
    init += ",";
    io::AppendDouble(rendered.first_view(1, i), &init);
    init += "\n";
  }
  return init;
}

}  // namespace hecal::report
