// The image front end's stages as text: see image_set_text.h.
#include "hecal/jobs/image_set_text.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <numbers>
#include <sstream>
#include <string_view>

#include "hecal/io/delimited_text.h"

namespace hecal::jobs {
namespace {

using io::FormatFixed;

std::string EstimatedIntrinsicsText(const vision::IntrinsicsResult& result, int views) {
  const pose::CameraModel& c = result.camera;
  const vision::IntrinsicsSigma& s = result.sigma;
  std::ostringstream out;
  out << "intrinsics: estimated from " << views << " images (cv::calibrateCamera), RMS "
      << FormatFixed(result.rms_px, 4) << " px; the points cover "
      << FormatFixed(100 * result.coverage, 0) << "% of the image, board normals spread over "
      << FormatFixed(result.normal_spread_deg, 1) << " deg\n"
      << "  fx " << FormatFixed(c.fx, 3) << " ± " << FormatFixed(s.fx, 3) << "  fy "
      << FormatFixed(c.fy, 3) << " ± " << FormatFixed(s.fy, 3) << "  cx " << FormatFixed(c.cx, 3)
      << " ± " << FormatFixed(s.cx, 3) << "  cy " << FormatFixed(c.cy, 3) << " ± "
      << FormatFixed(s.cy, 3) << " px (1 sigma)\n  ";
  constexpr std::array<std::string_view, 5> kNames = {"k1", "k2", "p1", "p2", "k3"};
  for (std::size_t k = 0; k < kNames.size(); ++k) {
    out << (k == 0 ? "" : "  ") << kNames[k] << " " << FormatFixed(c.distortion[k], 6) << " ± "
        << FormatFixed(s.distortion[k], 6);
  }
  out << "\n";
  return out.str();
}

}  // namespace

std::string ImageSetListedText(const vision::ImageSet& set, const vision::ImageSetOptions& options,
                               const std::string& caller) {
  std::ostringstream out;
  out << caller << ": " << set.images.size()
      << (set.sub_folders ? " station sub-folder(s)" : " image(s)") << " in " << options.images
      << ", target " << vision::Describe(set.target) << " (" << set.board.size() << " points)\n";
  return out.str();
}

std::string ImageSetIntrinsicsText(const vision::ImageSet& set,
                                   const vision::ImageSetOptions& options) {
  if (set.estimated) return EstimatedIntrinsicsText(*set.estimated, set.CountUsed());
  std::ostringstream out;
  out << "intrinsics: " << options.intrinsics << " (fx " << set.camera.fx << ", fy "
      << set.camera.fy << ", cx " << set.camera.cx << ", cy " << set.camera.cy << " px)\n";
  for (const std::string& note : set.camera_notes) out << "note: " << note << "\n";
  return out.str();
}

std::string ImageTableText(const std::vector<vision::ImageRecord>& images) {
  std::size_t width = 5;
  for (const vision::ImageRecord& image : images) width = std::max(width, image.name.size());
  std::ostringstream out;
  out << std::left << std::setw(static_cast<int>(width) + 2) << "image" << std::setw(11) << "status"
      << std::setw(11) << "points" << std::setw(10) << "sharp_px" << std::setw(9) << "rms_px"
      << std::setw(10) << "sigma_mm"
      << "sigma_deg\n";
  for (const vision::ImageRecord& image : images) {
    const vision::Detection& d = image.detection;
    out << std::setw(static_cast<int>(width) + 2) << image.name << std::setw(11)
        << vision::DetectionStatusName(d.status) << std::setw(11)
        << (std::to_string(d.num_points()) + "/" + std::to_string(d.total_points)) << std::setw(10)
        << FormatFixed(d.sharpness, 2);
    if (image.pose.has_value() && image.used()) {
      const Matrix6d& C = image.pose->covariance;
      const double sigma_deg =
          std::sqrt(C.topLeftCorner<3, 3>().trace() / 3.0) * 180.0 / std::numbers::pi;
      const double sigma_mm = std::sqrt(C.bottomRightCorner<3, 3>().trace() / 3.0) * 1e3;
      out << std::setw(9) << FormatFixed(image.pose->rms_px, 3) << std::setw(10)
          << FormatFixed(sigma_mm, 3) << FormatFixed(sigma_deg, 4) << "\n";
    } else if (!image.used()) {
      out << "skipped: " << image.skipped << "\n";
    } else {
      out << "\n";
    }
  }
  return out.str();
}

}  // namespace hecal::jobs
