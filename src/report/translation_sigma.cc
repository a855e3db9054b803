// The 1σ of a pose's translation along its parent frame's axes: see translation_sigma.h.
#include "hecal/report/translation_sigma.h"

#include <cassert>
#include <string>

namespace hecal::report {

Eigen::Matrix3d TranslationCovarianceInParent(const Pose& T, const Matrix6d& covariance) {
  const Eigen::Matrix3d& R = T.linear();
  const Eigen::Matrix3d C = R * covariance.bottomRightCorner<3, 3>() * R.transpose();
  return 0.5 * (C + C.transpose());
}

std::string_view ParentFrame(std::string_view pose_name) {
  assert(pose_name.substr(0, 2) == "T_");
  const std::string_view rest = pose_name.substr(2);
  return rest.substr(0, rest.find('_'));
}

namespace {

Eigen::Vector3d Sigma(const Pose& T, const Matrix6d& covariance) {
  return TranslationCovarianceInParent(T, covariance).diagonal().cwiseSqrt();
}

}  // namespace

void PrintTranslationSigmaInParent(std::ostream& out, std::string_view name,
                                   std::string_view pose_name, const Pose& T,
                                   const Matrix6d& covariance) {
  out << "  1σ of " << name << "'s translation along the " << ParentFrame(pose_name) << "'s axes: ("
      << Sigma(T, covariance).transpose() * 1000.0 << ") mm\n";
}

nlohmann::json TranslationSigmaInParentJson(std::string_view pose_name, const Pose& T,
                                            const Matrix6d& covariance, double scale) {
  const Eigen::Vector3d sd = Sigma(T, covariance) * scale;
  return {{"frame", std::string(ParentFrame(pose_name))},
          {"translation", {sd.x(), sd.y(), sd.z()}}};
}

}  // namespace hecal::report
