// A rendered contour sequence: see contour_rendering.h.
#include "hecal/jobs/contour_rendering.h"

#include "hecal/contour/contour_study.h"
#include "hecal/core/options_check.h"
#include "hecal/io/contour_file.h"
#include "hecal/report/contour_render_file.h"
#include "hecal/vision/contour_images.h"

namespace hecal::jobs {
namespace {

// The sequence with the target it is rendered with, the contour file's points given as `file`.
contour::SequenceRenderOptions WithTarget(const ContourRenderingOptions& options,
                                          const Eigen::Matrix2Xd& file) {
  contour::SequenceRenderOptions sequence = options.sequence;
  if (!options.contour.empty()) {
    sequence.target = file;
  } else if (sequence.target.cols() == 0) {
    sequence.target = contour::DefaultTarget();
  }
  return sequence;
}

}  // namespace

bool ContourRenderingOptions::IsValid(std::string* why) const {
  // A contour file's points are checked by the reader; the built-in target stands in for them.
  return WithTarget(*this, contour::DefaultTarget()).IsValid(why);
}

ContourRendering RenderContourSequence(
    const ContourRenderingOptions& options,
    const std::function<void(const std::string& name, const std::string& png)>& on_frame) {
  RequireValid(options);
  ContourRendering result;
  result.options = WithTarget(
      options, options.contour.empty() ? Eigen::Matrix2Xd() : io::ReadContourFile(options.contour));
  result.rendered = contour::RenderSequence(
      result.options, [&](const contour::RenderedFrame& frame, const contour::GrayImage& image) {
        const std::string name = report::RenderedFrameName(frame.index);
        const std::string png = vision::EncodePng(image, name);
        if (on_frame) on_frame(name, png);
      });
  result.init_csv = report::RenderInitCsv(result.rendered);
  result.truth_csv = report::RenderTruthCsv(result.options, result.rendered);
  return result;
}

}  // namespace hecal::jobs
