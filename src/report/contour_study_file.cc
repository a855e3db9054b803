// The result files of `hecal contour study`: see contour_study_file.h.
#include "hecal/report/contour_study_file.h"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "hecal/geometry/angle_units.h"
#include "hecal/report/svg_figure.h"

namespace hecal::report {
namespace {}  // namespace

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

std::string ContourStudyFigure(const contour::ContourStudyOptions& o,
                               const std::vector<contour::StudyStep>& steps) {
  std::vector<report::svg::Panel> panels;
  for (int j = 0; j < 6; ++j) {
    report::svg::Panel panel;
    panel.title = std::string(kStudyComponents[j]) + " error";
    panel.x_label = StudyMotionLabel(o.motion);
    panel.y_label = j < 3 ? "mm" : "deg";
    const auto add = [&](const std::string& label, bool dashed, const std::string& color,
                         const auto& mean, const auto& sd) {
      report::svg::Line centre, upper, lower;
      for (const contour::StudyStep& step : steps) {
        const double m = StudyDisplay(j, mean(step)(j)), s = StudyDisplay(j, sd(step)(j));
        for (report::svg::Line* line : {&centre, &upper, &lower}) line->x.push_back(step.value);
        centre.y.push_back(m);
        upper.y.push_back(m + 2 * s);
        lower.y.push_back(m - 2 * s);
      }
      centre.label = label + " mean";
      upper.label = label + " ±2σ";
      for (report::svg::Line* line : {&centre, &upper, &lower}) {
        line->dashed = dashed;
        line->color = color;
      }
      upper.width = lower.width = 1.0;
      panel.lines.push_back(centre);
      panel.lines.push_back(upper);
      panel.lines.push_back(lower);
    };
    add(
        "UT", false, "#1f77b4", [](const contour::StudyStep& s) { return s.ut_mean_error; },
        [](const contour::StudyStep& s) { return s.ut_sd; });
    add(
        "MC", true, "#d62728", [](const contour::StudyStep& s) { return s.mc_mean_error; },
        [](const contour::StudyStep& s) { return s.mc_sd; });
    panels.push_back(std::move(panel));
  }
  report::svg::FigureOptions options;
  options.title = "Pose error (mean ± 2σ) for a motion along " +
                  std::string(contour::StudyMotionName(o.motion)) + ": UT solid, Monte Carlo (" +
                  std::to_string(o.samples) + " samples) dashed";
  options.columns = 3;
  return report::svg::Figure(panels, options);
}

std::string ContourCovarianceFigure(const contour::ContourStudyOptions& o,
                                    const std::vector<contour::StudyStep>& steps, double at) {
  const contour::StudyStep& step = NearestStep(steps, at);
  std::vector<report::svg::Panel> panels;
  const auto error = [&](const Vector6d& pose, int j) {
    return StudyDisplay(j,
                        contour::PoseDifference(pose, step.truth, contour::RotationForm::kZyx)(j));
  };
  for (int a = 0; a < 6; ++a) {
    for (int b = a + 1; b < 6; ++b) {
      report::svg::Panel panel;
      panel.title = std::string(kStudyComponents[a]) + " – " + kStudyComponents[b];
      panel.x_label = std::string(kStudyComponents[a]) + (a < 3 ? " (mm)" : " (deg)");
      panel.y_label = std::string(kStudyComponents[b]) + (b < 3 ? " (mm)" : " (deg)");
      panel.legend = a == 0 && b == 1;
      report::svg::Points samples{
          .label = "MC poses", .color = "#2ca02c", .size = 1.0, .opacity = 0.5};
      for (const Vector6d& p : step.mc_poses) samples.xy.emplace_back(error(p, a), error(p, b));
      report::svg::Points sigma{.label = "sigma points",
                                .color = "#1f77b4",
                                .marker = report::svg::Points::Marker::kCross,
                                .size = 4.0};
      for (const Vector6d& p : step.sigma_poses) sigma.xy.emplace_back(error(p, a), error(p, b));
      const auto block = [&](const Matrix6d& C) {
        Eigen::Matrix2d B;
        B << StudyDisplay(a, StudyDisplay(a, C(a, a))), StudyDisplay(a, StudyDisplay(b, C(a, b))),
            StudyDisplay(a, StudyDisplay(b, C(b, a))), StudyDisplay(b, StudyDisplay(b, C(b, b)));
        return B;
      };
      report::svg::Points mean{.label = "MC mean", .color = "#d62728", .size = 3.0};
      mean.xy.emplace_back(StudyDisplay(a, step.mc_mean_error(a)),
                           StudyDisplay(b, step.mc_mean_error(b)));
      panel.points = {samples, sigma, mean};
      panel.ellipses.push_back({.label = "MC 2σ",
                                .centre = mean.xy.front(),
                                .covariance = block(step.mc_covariance),
                                .color = "#d62728",
                                .dashed = true});
      panel.ellipses.push_back({.label = "UT 2σ",
                                .centre = Eigen::Vector2d(StudyDisplay(a, step.ut_mean_error(a)),
                                                          StudyDisplay(b, step.ut_mean_error(b))),
                                .covariance = block(step.ut_covariance),
                                .color = "#1f77b4"});
      panels.push_back(std::move(panel));
    }
  }
  std::ostringstream title;
  title << "Pose covariance, " << contour::StudyMotionName(o.motion) << " = " << step.value
        << (contour::IsRotation(o.motion) ? "°" : " mm")
        << ": errors (mm, deg), Monte Carlo dashed, UT solid, 2σ";
  report::svg::FigureOptions options;
  options.title = title.str();
  options.columns = 5;
  options.panel_width = 300;
  options.panel_height = 240;
  return report::svg::Figure(panels, options);
}

}  // namespace hecal::report
