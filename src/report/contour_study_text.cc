// The contour study as text: see contour_study_text.h.
#include "hecal/report/contour_study_text.h"

#include <cmath>
#include <iomanip>

#include "hecal/report/contour_study_file.h"

namespace hecal::report {

void PrintContourStudy(std::ostream& out, const contour::ContourStudyOptions& o,
                       const std::vector<contour::StudyStep>& steps) {
  out << "contour study: motion " << contour::StudyMotionName(o.motion) << ", Z0 " << o.z0_mm
      << " mm, f " << o.focal_mm << " mm (" << o.focal_mm / o.pixel_size_mm << " px), σ "
      << o.pixel_noise << " px, " << o.target.cols() << " control points, Monte Carlo " << o.samples
      << " samples (seed " << o.seed << "), UT 13 points\n";
  out << "errors against the true motion: mean ± sd (mm, deg); ratio = UT sd / MC sd; * = bias "
         "flag (docs/contour.md#the-bias-check)\n";
  out << std::fixed;
  for (const contour::StudyStep& step : steps) {
    out << std::setprecision(2) << StudyMotionLabel(o.motion) << " = " << step.value << "\n";
    for (int j = 0; j < 6; ++j) {
      out << std::setprecision(4) << "  " << kStudyComponents[j] << "  MC " << std::setw(9)
          << StudyDisplay(j, step.mc_mean_error(j)) << " ± " << std::setw(8)
          << StudyDisplay(j, step.mc_sd(j)) << "   UT " << std::setw(9)
          << StudyDisplay(j, step.ut_mean_error(j)) << " ± " << std::setw(8)
          << StudyDisplay(j, step.ut_sd(j)) << "   ratio " << std::setprecision(3)
          << step.ut_sd(j) / step.mc_sd(j) << (step.bias[static_cast<std::size_t>(j)] ? " *" : "")
          << "\n";
    }
    if (step.mc_failures > 0) out << "  (" << step.mc_failures << " Monte Carlo samples failed)\n";
  }
  // The largest Monte Carlo correlation of each pair over the sweep.
  out << "largest |correlation| over the steps (Monte Carlo):";
  for (int a = 0; a < 6; ++a) {
    for (int b = a + 1; b < 6; ++b) {
      double worst = 0.0;
      for (const contour::StudyStep& step : steps) {
        const double r = step.mc_covariance(a, b) /
                         std::sqrt(step.mc_covariance(a, a) * step.mc_covariance(b, b));
        if (std::abs(r) > std::abs(worst)) worst = r;
      }
      if (std::abs(worst) >= 0.3) {
        out << std::setprecision(2) << " " << kStudyComponents[a] << "–" << kStudyComponents[b]
            << " " << worst;
      }
    }
  }
  out << " (pairs below 0.3 not shown)\n";
  out.unsetf(std::ios::floatfield);
}

}  // namespace hecal::report
