// A tracked frame as one line of text: see contour_track_text.h.
#include "hecal/report/contour_track_text.h"

#include <array>
#include <cstdio>
#include <string_view>

#include "hecal/geometry/angle_units.h"

namespace hecal::report {

std::string ContourTrackLine(const contour::TrackedImage& image, contour::RotationForm form) {
  const std::array<std::string_view, 6> names = contour::PoseParameterNames(form);
  const contour::SequenceFrame& frame = image.frame;
  char line[256];
  std::snprintf(line, sizeof line, "%4d %-24s %-8s edges %3d/%3d  σ %.3f px", frame.tracked.frame,
                image.image.c_str(), std::string(contour::FrameStatusName(frame.status)).c_str(),
                frame.tracked.edges_used, frame.tracked.edges_searched, frame.tracked.sigma);
  std::string text = line;
  if (frame.pose) {
    const Vector6d& p = frame.pose->parameters;
    std::snprintf(line, sizeof line, "  T = (%.3f, %.3f, %.3f)  %s,%s,%s = (%.3f, %.3f, %.3f)°",
                  p(0), p(1), p(2), std::string(names[3]).c_str(), std::string(names[4]).c_str(),
                  std::string(names[5]).c_str(), p(3) * kDegreesPerRadian, p(4) * kDegreesPerRadian,
                  p(5) * kDegreesPerRadian);
    text += line;
    if (frame.pose->any_biased) text += "  (bias)";
  }
  return text + "\n";
}

}  // namespace hecal::report
