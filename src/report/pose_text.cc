// The pose from points as readable text: see pose_text.h.
#include "hecal/report/pose_text.h"

#include <iomanip>
#include <string_view>

#include "hecal/geometry/angle_units.h"
#include "hecal/geometry/so3.h"

namespace hecal::report {
namespace {}  // namespace

void PrintPoseEstimate(std::ostream& out, const pose::PoseEstimate& estimate, std::size_t points,
                       io::LengthUnit unit) {
  const double scale = 1.0 / io::MetresPer(unit);
  const std::string_view unit_name = io::UnitName(unit);
  const Pose& T = estimate.T_camera_target;
  const Eigen::Vector3d rvec = so3::Log(T.linear());
  out << std::setprecision(6) << std::fixed;
  out << "method " << estimate.method << " (" << points << " points)\n";
  out << "T_camera_target (x_camera = R x_target + t)\n";
  for (int r = 0; r < 3; ++r) {
    out << "  [";
    for (int c = 0; c < 3; ++c) out << std::setw(11) << T.linear()(r, c);
    out << " |" << std::setw(12) << T.translation()(r) * scale << " ]\n";
  }
  out << "  t = (" << (T.translation() * scale).transpose() << ") " << unit_name << "\n";
  out << "  rvec = (" << rvec.transpose() << ") rad, " << rvec.norm() * kDegreesPerRadian
      << " deg\n";
  if (estimate.covariance) {
    const Vector6d sd = estimate.covariance->diagonal().cwiseSqrt();
    out << "  1σ rotation (rx, ry, rz) = (" << sd.head<3>().transpose() * kDegreesPerRadian
        << ") deg\n";
    out << "  1σ translation (tx, ty, tz) = (" << sd.tail<3>().transpose() * scale << ") "
        << unit_name << "\n";
  }
  out << std::setprecision(4) << "reprojection RMS " << estimate.rms_px << " px per point";
  if (estimate.covariance) {
    out << ", pixel σ " << estimate.sigma_px << " px per axis ("
        << (estimate.sigma_source == pose::SigmaSource::kGiven ? "given"
                                                               : "estimated from the residuals")
        << ")";
  } else {
    out << " (no covariance: " << estimate.method << " is not refined)";
  }
  out << "\n";
  out.unsetf(std::ios::floatfield);
}

}  // namespace hecal::report
