// `hecal contour study`: the contour paper's experiments (contour/contour_study.h) from the command
// line.
//
//   hecal contour study --motion tx|ty|tz|rx|ry|rz --from A --to B --steps N
//         [--pixel-noise 0.5] [--z0 5000] [--focal 50] [--pixel-size 0.0083] [--contour FILE]
//         [--samples 5000] [--seed 1] [--threads 0] [--ut-w0 0]
//         [--output study.csv] [--plot study.svg] [--covariance-plot cov.svg [--covariance-at V]]
// Lengths in mm, angles in degrees (the contour paper's units). --output writes a comment line with
// the random seed and the sample count, then one row per step and per
// pose component: motion,value,component,mc_mean_error,mc_std,ut_mean_error,ut_std,bias
// (component Tx,Ty,Tz,Rx,Ry,Rz; errors against the true motion; bias 1 when the bias check
// flags the component). --plot (default: the CSV's name with .svg) draws the contour paper's Fig.
// 3: mean error ± 2σ against the motion, UT solid, Monte Carlo dashed, one panel per component.
// --covariance-plot draws Fig. 4 at the step nearest --covariance-at (default: --from): every
// 2×2 block of the pose covariance as 2σ ellipses (UT solid, Monte Carlo dashed) with 1000
// Monte Carlo poses and the 13 sigma points. Stdout: a table per step and the largest
// correlations. Every file is written atomically, all or none (io/atomic_file.h: the paths are
// checked before the study runs), and only after the whole study ran. Bounds (bounds.h):
// --steps 1 … 10000, --samples 2 … 10^6 with steps × samples ≤ 10^8, --threads 0 … 256,
// --pixel-noise 0 … 100 px, --seed 0 … 2^64 − 1.
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iomanip>
#include <memory>
#include <numbers>
#include <sstream>

#include "bounds.h"
#include "contour.h"
#include "hecal/contour/contour_study.h"
#include "hecal/core/error.h"
#include "hecal/io/atomic_file.h"
#include "hecal/report/svg_figure.h"

namespace hecal::cli {
namespace {

constexpr double kDegrees = 180.0 / std::numbers::pi;
constexpr std::array<const char*, 6> kComponents = {"Tx", "Ty", "Tz", "Rx", "Ry", "Rz"};

struct StudyCommandOptions {
  std::string motion;
  std::string from, to, steps;
  std::string pixel_noise = "0.5";
  std::string z0 = "5000";
  std::string focal = "50";
  std::string pixel_size = "0.0083";
  std::string contour;
  std::string samples = "5000";
  std::string seed = "1";
  std::string threads = "0";
  std::string ut_w0 = "0";
  std::string output, plot, covariance_plot, covariance_at;
};

// Display units: mm for Tx..Tz, degrees for Rx..Rz.
double Display(int component, double value) {
  return component < 3 ? value : value * kDegrees;
}

std::string Csv(const contour::ContourStudyOptions& o,
                const std::vector<contour::StudyStep>& steps) {
  std::ostringstream out;
  out << std::setprecision(10);
  out << "# hecal contour study: seed " << o.seed << ", " << o.samples
      << " Monte Carlo samples per step\n";
  out << "motion,value,component,mc_mean_error,mc_std,ut_mean_error,ut_std,bias\n";
  for (const contour::StudyStep& step : steps) {
    for (int j = 0; j < 6; ++j) {
      out << contour::StudyMotionName(o.motion) << ',' << step.value << ',' << kComponents[j] << ','
          << Display(j, step.mc_mean_error(j)) << ',' << Display(j, step.mc_sd(j)) << ','
          << Display(j, step.ut_mean_error(j)) << ',' << Display(j, step.ut_sd(j)) << ','
          << (step.bias[static_cast<std::size_t>(j)] ? 1 : 0) << '\n';
    }
  }
  return out.str();
}

std::string MotionLabel(contour::StudyMotion motion) {
  return std::string(contour::StudyMotionName(motion)) +
         (contour::IsRotation(motion) ? " (deg)" : " (mm)");
}

std::string Figure3(const contour::ContourStudyOptions& o,
                    const std::vector<contour::StudyStep>& steps) {
  std::vector<report::svg::Panel> panels;
  for (int j = 0; j < 6; ++j) {
    report::svg::Panel panel;
    panel.title = std::string(kComponents[j]) + " error";
    panel.x_label = MotionLabel(o.motion);
    panel.y_label = j < 3 ? "mm" : "deg";
    const auto add = [&](const std::string& label, bool dashed, const std::string& color,
                         const auto& mean, const auto& sd) {
      report::svg::Line centre, upper, lower;
      for (const contour::StudyStep& step : steps) {
        const double m = Display(j, mean(step)(j)), s = Display(j, sd(step)(j));
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

std::string Figure4(const contour::ContourStudyOptions& o, const contour::StudyStep& step) {
  std::vector<report::svg::Panel> panels;
  const auto error = [&](const Vector6d& pose, int j) {
    return Display(j, contour::PoseDifference(pose, step.truth, contour::RotationForm::kZyx)(j));
  };
  for (int a = 0; a < 6; ++a) {
    for (int b = a + 1; b < 6; ++b) {
      report::svg::Panel panel;
      panel.title = std::string(kComponents[a]) + " – " + kComponents[b];
      panel.x_label = std::string(kComponents[a]) + (a < 3 ? " (mm)" : " (deg)");
      panel.y_label = std::string(kComponents[b]) + (b < 3 ? " (mm)" : " (deg)");
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
        B << Display(a, Display(a, C(a, a))), Display(a, Display(b, C(a, b))),
            Display(a, Display(b, C(b, a))), Display(b, Display(b, C(b, b)));
        return B;
      };
      report::svg::Points mean{.label = "MC mean", .color = "#d62728", .size = 3.0};
      mean.xy.emplace_back(Display(a, step.mc_mean_error(a)), Display(b, step.mc_mean_error(b)));
      panel.points = {samples, sigma, mean};
      panel.ellipses.push_back({.label = "MC 2σ",
                                .centre = mean.xy.front(),
                                .covariance = block(step.mc_covariance),
                                .color = "#d62728",
                                .dashed = true});
      panel.ellipses.push_back({.label = "UT 2σ",
                                .centre = Eigen::Vector2d(Display(a, step.ut_mean_error(a)),
                                                          Display(b, step.ut_mean_error(b))),
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

void PrintTable(std::ostream& out, const contour::ContourStudyOptions& o,
                const std::vector<contour::StudyStep>& steps) {
  out << "contour study: motion " << contour::StudyMotionName(o.motion) << ", Z0 " << o.z0_mm
      << " mm, f " << o.focal_mm << " mm (" << o.focal_mm / o.pixel_size_mm << " px), σ "
      << o.pixel_noise << " px, " << o.target.cols() << " control points, Monte Carlo " << o.samples
      << " samples (seed " << o.seed << "), UT 13 points\n";
  out << "errors against the true motion: mean ± sd (mm, deg); ratio = UT sd / MC sd; * = bias "
         "flag (docs/contour.md#the-bias-check)\n";
  out << std::fixed;
  for (const contour::StudyStep& step : steps) {
    out << std::setprecision(2) << MotionLabel(o.motion) << " = " << step.value << "\n";
    for (int j = 0; j < 6; ++j) {
      out << std::setprecision(4) << "  " << kComponents[j] << "  MC " << std::setw(9)
          << Display(j, step.mc_mean_error(j)) << " ± " << std::setw(8) << Display(j, step.mc_sd(j))
          << "   UT " << std::setw(9) << Display(j, step.ut_mean_error(j)) << " ± " << std::setw(8)
          << Display(j, step.ut_sd(j)) << "   ratio " << std::setprecision(3)
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
        out << std::setprecision(2) << " " << kComponents[a] << "–" << kComponents[b] << " "
            << worst;
      }
    }
  }
  out << " (pairs below 0.3 not shown)\n";
  out.unsetf(std::ios::floatfield);
}

void RunStudy(const StudyCommandOptions& flags, const Io& io) {
  contour::ContourStudyOptions o;
  const std::optional<contour::StudyMotion> motion = contour::ParseStudyMotion(flags.motion);
  if (!motion) {
    throw InputError("--motion", 0, "unknown motion '" + flags.motion + "'",
                     "use one of tx, ty, tz, rx, ry, rz");
  }
  o.motion = *motion;
  o.from = ParseNumber("--from", flags.from, "(one number)");
  o.to = ParseNumber("--to", flags.to, "(one number)");
  o.steps = ParseCount("--steps", flags.steps, 1, kMaxSteps, "the number of motion values");
  o.pixel_noise = ParseNumber("--pixel-noise", flags.pixel_noise, "(one number)");
  CheckPixelSigma("--pixel-noise", o.pixel_noise, /*zero_allowed=*/true);
  o.z0_mm = ParseNumber("--z0", flags.z0, "(one number)");
  o.focal_mm = ParseNumber("--focal", flags.focal, "(one number)");
  o.pixel_size_mm = ParseNumber("--pixel-size", flags.pixel_size, "(one number)");
  if (!flags.contour.empty()) o.target = ReadContourFile(flags.contour);
  o.samples = ParseCount("--samples", flags.samples, 2, kMaxContourSamples,
                         "the number of Monte Carlo samples per step");
  if (std::int64_t{o.samples} * o.steps > kMaxContourSolves) {
    throw InputError("--samples", 0,
                     std::to_string(o.steps) + " steps x " + std::to_string(o.samples) +
                         " samples is more than " + std::to_string(kMaxContourSolves) +
                         " Monte Carlo solves",
                     "give fewer --steps or --samples");
  }
  o.seed = ParseSeed("--seed", flags.seed);
  o.threads = ParseThreads("--threads", flags.threads);
  o.unscented.unscented = uncertainty::UnscentedParameters::Symmetric(
      ParseNumber("--ut-w0", flags.ut_w0, "(one number)"));
  std::string why;
  if (!o.unscented.unscented.IsValid(6, &why)) {
    throw InputError("--ut-w0", 0, why, "give w0 < 1 (default 0)");
  }
  if (!flags.covariance_plot.empty()) o.keep_samples = 1000;
  contour::ValidateStudyOptions(o);
  std::string plot = flags.plot;
  if (plot.empty() && !flags.output.empty()) {
    plot = std::filesystem::path(flags.output).replace_extension(".svg").string();
  }
  io::CheckOutputs(
      {{"--output", flags.output}, {"--plot", plot}, {"--covariance-plot", flags.covariance_plot}},
      {{"--contour", flags.contour}});
  const double covariance_at =
      flags.covariance_at.empty()
          ? o.from
          : ParseNumber("--covariance-at", flags.covariance_at, "(one number)");

  const std::vector<contour::StudyStep> steps = contour::RunContourStudy(o);
  PrintTable(io.out, o, steps);

  std::vector<io::OutputFile> outputs;
  if (!flags.output.empty()) outputs.push_back({"--output", flags.output, Csv(o, steps)});
  if (!plot.empty()) outputs.push_back({"--plot", plot, Figure3(o, steps)});
  if (!flags.covariance_plot.empty()) {
    const contour::StudyStep* nearest = &steps.front();
    for (const contour::StudyStep& step : steps) {
      if (std::abs(step.value - covariance_at) < std::abs(nearest->value - covariance_at)) {
        nearest = &step;
      }
    }
    outputs.push_back({"--covariance-plot", flags.covariance_plot, Figure4(o, *nearest)});
  }
  io::WriteFilesAtomically(outputs);
  for (const std::string& file : {flags.output, plot, flags.covariance_plot}) {
    if (!file.empty()) io.out << "wrote " << file << "\n";
  }
}

}  // namespace

void AddContourStudyCommand(CLI::App& contour, const Io& io) {
  auto flags = std::make_shared<StudyCommandOptions>();
  CLI::App* study = contour.add_subcommand("study",
                                           "The contour paper's experiments: UT vs Monte Carlo "
                                           "along one motion (docs/contour.md#the-experiments)");
  study->add_option("--motion", flags->motion, "tx|ty|tz|rx|ry|rz")->required();
  study->add_option("--from", flags->from, "First value (mm or degrees)")->required();
  study->add_option("--to", flags->to, "Last value (mm or degrees)")->required();
  study->add_option("--steps", flags->steps, "Number of values from --from to --to (1 to 10000)")
      ->required();
  study->add_option("--pixel-noise", flags->pixel_noise,
                    "σ per image coordinate, px (0.5; 0 to 100)");
  study->add_option("--z0", flags->z0, "Initial distance, mm (5000)");
  study->add_option("--focal", flags->focal, "Focal length, mm (50)");
  study->add_option("--pixel-size", flags->pixel_size, "Pixel size, mm (0.0083)");
  study->add_option("--contour", flags->contour,
                    "Target control points, CSV x,y in mm on the target plane (default: built in)");
  study->add_option("--samples", flags->samples,
                    "Monte Carlo samples per step (5000; 2 to 1000000)");
  study->add_option("--seed", flags->seed, "Random seed (1; 0 to 2^64-1)");
  study->add_option("--threads", flags->threads, "Threads, 0 to 256 (0: every core)");
  study->add_option("--ut-w0", flags->ut_w0, "UT centre weight w0 (0)");
  study->add_option("--output", flags->output,
                    "CSV: motion,value,component,mc_mean_error,mc_std,ut_mean_error,ut_std,bias");
  study->add_option("--plot", flags->plot, "Fig. 3 SVG (default: --output with .svg)");
  study->add_option("--covariance-plot", flags->covariance_plot, "Fig. 4 SVG");
  study->add_option("--covariance-at", flags->covariance_at,
                    "Motion value of the covariance plot (default: --from)");
  study->callback([flags, io] { RunStudy(*flags, io); });
}

}  // namespace hecal::cli
