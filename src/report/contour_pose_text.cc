// The camera motion of one shape vector as text: see contour_pose_text.h.
#include "hecal/report/contour_pose_text.h"

#include <array>
#include <cmath>
#include <iomanip>
#include <optional>
#include <string_view>

#include "hecal/contour/affine_pose.h"
#include "hecal/contour/pose_uncertainty.h"
#include "hecal/geometry/angle_units.h"

namespace hecal::report {

void PrintContourPose(std::ostream& out, const contour::ShapePose& result) {
  const contour::ContourPose& pose = result.pose;
  const std::optional<contour::ContourPoseUncertainty>& ut = result.uncertainty;
  const std::string_view sequence = contour::RotationSequence(pose.form);
  const std::array<std::string_view, 6> names = contour::PoseParameterNames(pose.form);
  out << std::setprecision(9);
  out << "translation (Tx, Ty, Tz) = (" << pose.translation.transpose() << ")  [unit of --z0]\n";
  out << "rotation matrix\n";
  for (int r = 0; r < 3; ++r) out << "  " << pose.rotation.row(r) << "\n";
  out << "euler " << sequence << " = (" << pose.euler.transpose() << ") rad = ("
      << (pose.euler * kDegreesPerRadian).transpose() << ") deg\n";
  if (ut) {
    out << "UT (13 sigma points), 1σ:";
    for (std::size_t j = 0; j < 6; ++j) {
      const double sd = std::sqrt(ut->covariance(static_cast<int>(j), static_cast<int>(j)));
      out << " " << names[j] << " " << (j < 3 ? sd : sd * kDegreesPerRadian) << (j < 3 ? "" : "°")
          << (ut->biased[j] ? " (biased)" : "");
    }
    out << "\n";
    if (ut->any_biased) {
      out << "bias: the UT mean departs from the pose of the mean shape "
             "(docs/contour.md#the-bias-check: tilt near "
             "zero; the Necker sign fold)\n";
    }
  }
}

}  // namespace hecal::report
