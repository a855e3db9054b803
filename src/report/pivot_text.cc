#include "hecal/report/pivot_text.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "hecal/geometry/angle_units.h"

namespace hecal::report {
namespace {

// "x 12.345 ± 0.012   y ...   z ..." in millimetres.
std::string PointText(const Eigen::Vector3d& point, const Eigen::Matrix3d& covariance) {
  std::string text;
  const char* axes[] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) {
    char item[64];
    std::snprintf(item, sizeof item, "%s%s %.3f ± %.3f", k > 0 ? "   " : "", axes[k],
                  point(k) * 1e3, std::sqrt(covariance(k, k)) * 1e3);
    text += item;
  }
  return text;
}

}  // namespace

void PrintPivotSummary(std::ostream& out, const PivotDocument& document) {
  const estimation::PivotResult& r = document.result;
  int used = 0, flagged = 0;
  std::string flagged_ids;
  for (size_t i = 0; i < r.stations.size(); ++i) {
    used += r.stations[i].used ? 1 : 0;
    if (!r.stations[i].outlier) continue;
    ++flagged;
    char item[64];
    std::snprintf(item, sizeof item, "%s%s (%.1f sigma)", flagged_ids.empty() ? "" : ", ",
                  document.station_ids.at(i).c_str(), r.stations[i].standardized);
    flagged_ids += item;
  }
  char line[256];
  out << "pivot calibration (mm, 1 sigma):\n";
  out << "  tip in flange:  " << PointText(r.tip, r.covariance.topLeftCorner<3, 3>()) << "\n";
  out << "  pivot in base:  " << PointText(r.pivot, r.covariance.bottomRightCorner<3, 3>()) << "\n";
  std::snprintf(line, sizeof line, "  tip length:     %.3f mm\n", r.tip.norm() * 1e3);
  out << line;
  std::snprintf(line, sizeof line, "  RMS residual:   %.4f mm (chi-square %.1f / %d dof)\n",
                r.rms * 1e3, r.chi_square, r.dof);
  out << line;
  std::snprintf(line, sizeof line, "  robot noise:    %.4g mm / %.4g deg per axis (%s)\n",
                r.sigma.translation * 1e3, r.sigma.rotation * kDegreesPerRadian,
                r.sigma_estimated ? "estimated" : "given");
  out << line;
  std::snprintf(line, sizeof line, "  stations:       %d of %zu used, %d flagged", used,
                r.stations.size(), flagged);
  out << line;
  if (flagged > 0) {
    out << ": " << flagged_ids
        << (document.outlier_rejection && used < static_cast<int>(r.stations.size()) ? " (left out)"
                                                                                     : " (kept)");
  }
  out << "\n";
  for (const std::string& warning : r.warnings) out << "warning: " << warning << "\n";
}

}  // namespace hecal::report
