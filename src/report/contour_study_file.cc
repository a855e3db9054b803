// The result files of `hecal contour study`: see contour_study_file.h.
#include "hecal/report/contour_study_file.h"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "hecal/geometry/angle_units.h"

namespace hecal::report {
double StudyDisplay(int component, double value) {
  return component < 3 ? value : value * kDegreesPerRadian;
}

std::string StudyMotionLabel(contour::StudyMotion motion) {
  return std::string(contour::StudyMotionName(motion)) +
         (contour::IsRotation(motion) ? " (deg)" : " (mm)");
}

const contour::StudyStep& NearestStep(const std::vector<contour::StudyStep>& steps, double at) {
  const contour::StudyStep* nearest = &steps.front();
  for (const contour::StudyStep& step : steps) {
    if (std::abs(step.value - at) < std::abs(nearest->value - at)) nearest = &step;
  }
  return *nearest;
}

std::string ContourStudyCsv(const contour::ContourStudyOptions& o,
                            const std::vector<contour::StudyStep>& steps) {
  std::ostringstream out;
  out << std::setprecision(10);
  out << "# hecal contour study: seed " << o.seed << ", " << o.samples
      << " Monte Carlo samples per step\n";
  out << "motion,value,component,mc_mean_error,mc_std,ut_mean_error,ut_std,bias\n";
  for (const contour::StudyStep& step : steps) {
    for (int j = 0; j < 6; ++j) {
      out << contour::StudyMotionName(o.motion) << ',' << step.value << ',' << kStudyComponents[j]
          << ',' << StudyDisplay(j, step.mc_mean_error(j)) << ',' << StudyDisplay(j, step.mc_sd(j))
          << ',' << StudyDisplay(j, step.ut_mean_error(j)) << ',' << StudyDisplay(j, step.ut_sd(j))
          << ',' << (step.bias[static_cast<std::size_t>(j)] ? 1 : 0) << '\n';
    }
  }
  return out.str();
}

nlohmann::json ContourStudyPageData(const contour::ContourStudyOptions& o,
                                    const std::vector<contour::StudyStep>& steps, double at,
                                    const std::string& title) {
  using nlohmann::json;
  const auto display = [](const Vector6d& v) {
    json out = json::array();
    for (int j = 0; j < 6; ++j) out.push_back(StudyDisplay(j, v(j)));
    return out;
  };
  json rows = json::array();
  for (const contour::StudyStep& step : steps) {
    rows.push_back({{"value", step.value},
                    {"mc_mean", display(step.mc_mean_error)},
                    {"mc_sd", display(step.mc_sd)},
                    {"ut_mean", display(step.ut_mean_error)},
                    {"ut_sd", display(step.ut_sd)},
                    {"bias", step.bias}});
  }
  const contour::StudyStep& step = NearestStep(steps, at);
  const auto covariance = [](const Matrix6d& C) {
    json out = json::array();
    for (int a = 0; a < 6; ++a) {
      json row = json::array();
      for (int b = 0; b < 6; ++b) row.push_back(StudyDisplay(a, StudyDisplay(b, C(a, b))));
      out.push_back(std::move(row));
    }
    return out;
  };
  const auto errors = [&](const std::vector<Vector6d>& poses) {
    json out = json::array();
    for (const Vector6d& pose : poses) {
      out.push_back(
          display(contour::PoseDifference(pose, step.truth, contour::RotationForm::kZyx)));
    }
    return out;
  };
  json units = json::array();
  for (int j = 0; j < 6; ++j) units.push_back(j < 3 ? "mm" : "deg");
  return {{"kind", "contour_study"},
          {"title", title},
          {"motion", std::string(contour::StudyMotionName(o.motion))},
          {"motion_label", StudyMotionLabel(o.motion)},
          {"seed", o.seed},
          {"samples", o.samples},
          {"pixel_noise", o.pixel_noise},
          {"z0_mm", o.z0_mm},
          {"focal_mm", o.focal_mm},
          {"pixel_size_mm", o.pixel_size_mm},
          {"components", kStudyComponents},
          {"units", units},
          {"steps", rows},
          {"covariance",
           {{"value", step.value},
            {"mc_mean", display(step.mc_mean_error)},
            {"ut_mean", display(step.ut_mean_error)},
            {"mc_covariance", covariance(step.mc_covariance)},
            {"ut_covariance", covariance(step.ut_covariance)},
            {"mc_samples", errors(step.mc_poses)},
            {"sigma_points", errors(step.sigma_poses)}}}};
}

}  // namespace hecal::report
