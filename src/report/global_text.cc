// The target-free calibration's result as text: see global_text.h.
#include "hecal/report/global_text.h"

#include <iomanip>
#include <string_view>

#include "hecal/geometry/so3.h"
#include "hecal/handeye/problem.h"
#include "hecal/report/translation_sigma.h"

namespace hecal::report {

void PrintGlobalSummary(std::ostream& out, const GlobalCalibrationResult& result,
                        io::LengthUnit unit) {
  const std::string_view units = io::UnitName(unit);
  const double metres = io::MetresPer(unit);
  const handeye::Setup setup = result.options.setup;
  const estimation::EpipolarPolish& polish = result.robot_noise.polish;
  const estimation::EpipolarNoise& noise = result.noise;
  const global::Certificate& c = result.certificate;
  const Pose& X = polish.X;
  const Vector6d sd = polish.covariance.diagonal().cwiseSqrt();
  out << "method global (" << handeye::SetupName(setup) << ", target-free)\n"
      << handeye::XFrameName(setup) << ": rotation vector [rad] "
      << so3::Log(X.linear()).transpose() << ", translation [" << units << "] "
      << (X.translation() / metres).transpose() << "\n"
      << "  1 sigma: rotation [rad] " << sd.head<3>().transpose() << ", translation [" << units
      << "] " << (sd.tail<3>() / metres).transpose() << "\n"
      << "  1 sigma of the translation along the " << ParentFrame(handeye::XFrameName(setup))
      << "'s axes [" << units << "] "
      << (TranslationCovarianceInParent(X, polish.covariance).diagonal().cwiseSqrt() / metres)
             .transpose()
      << "\n"
      << (result.robot_noise.robot_given ? "  noise (robot given, ray estimated): ray [rad] "
                                         : "  noise (estimated): ray [rad] ")
      << noise.ray_sigma << ", robot per pose: rotation [rad] " << noise.robot_rotation_sigma
      << ", translation [" << units << "] " << noise.robot_translation_sigma / metres << "\n"
      << std::setprecision(4) << "certificate: max ray error in [" << c.lower << ", " << c.upper
      << "] rad" << (c.certified ? " (certified)" : " (gap not closed)") << ", " << c.cubes
      << " cubes, " << c.lps << " LPs, " << c.seconds << " s\n"
      << "matches: " << result.inliers << " inliers, " << result.removed.size()
      << " removed (L∞ threshold " << result.threshold
      << " rad, then the re-check at the polished X)\n";
}

}  // namespace hecal::report
