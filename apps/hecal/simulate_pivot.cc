// `hecal simulate --pivot`: see simulate_pivot.h.
#include "simulate_pivot.h"

#include <cstdio>

#include "bounds.h"

namespace hecal::cli {
namespace {

// Trial 0 of the first setting as a pose table with ids, the truth in its comments.
std::string PivotPoseFile(const jobs::PivotStudyOptions& options) {
  const sim::PivotScene scene =
      jobs::PivotStudyTrial(options, options.sigmas.front(), options.stations.front(), 0);
  io::PoseTable table;
  for (size_t i = 0; i < scene.T_base_flange.size(); ++i) {
    io::PoseRow row;
    row.pose = scene.T_base_flange[i];
    row.id = std::to_string(i + 1);
    table.rows.push_back(row);
  }
  io::PoseWriteOptions write;
  write.units = io::LengthUnit::kMillimetre;
  char truth[256];
  std::snprintf(truth, sizeof truth,
                "truth: tip_mm (flange) %.6f %.6f %.6f, pivot_mm (base) %.6f %.6f %.6f; noise %g "
                "mm / %g deg per axis",
                scene.tip.x() * 1e3, scene.tip.y() * 1e3, scene.tip.z() * 1e3,
                scene.pivot.x() * 1e3, scene.pivot.y() * 1e3, scene.pivot.z() * 1e3,
                options.sigmas.front().mm, options.sigmas.front().deg);
  write.comments = {"hecal simulate --pivot: T_base_flange, a tool tip held at one point", truth};
  return io::FormatPoseTable(table, write);
}

void PrintPivotStudy(const jobs::PivotStudy& study, const Io& io) {
  char line[256];
  std::snprintf(
      line, sizeof line,
      "hecal simulate --pivot: seed %llu, %d trials per setting, tilt +-%g deg about each "
      "flange axis\n",
      static_cast<unsigned long long>(study.options.seed), study.options.trials,
      study.options.max_tilt_deg);
  io.out << line;
  io.out << "sigma mm/deg  stations  noise      tip RMSE mm  pivot RMSE mm  mean NEES [95% band]  "
            "tip NEES  1-sigma  2-sigma  failed\n";
  for (const jobs::PivotStudyRow& row : study.rows) {
    char sigma[32];
    std::snprintf(sigma, sizeof sigma, "%g/%g", row.sigma.mm, row.sigma.deg);
    std::snprintf(
        line, sizeof line,
        "%-12s  %8d  %-9s  %11.4f  %13.4f  %5.2f [%4.2f, %4.2f]  %8.2f  %6.1f%%  %6.1f%%  "
        "%6d\n",
        sigma, row.stations, row.estimated ? "estimated" : "given", row.tip_rmse * 1e3,
        row.pivot_rmse * 1e3, row.mean_nees, row.nees_low, row.nees_high, row.mean_tip_nees,
        100.0 * row.coverage_1sigma, 100.0 * row.coverage_2sigma, row.failures);
    io.out << line;
  }
  io.out << "NEES of (tip, pivot), 6 dof: a consistent covariance has its mean in the band and "
            "covers 68.3% / 95.4%;\nwith the noise estimated the mean is 6 (3m-6)/(3m-8) by "
            "design (m stations; docs/pivot.md).\n";
}

}  // namespace

void AddPivotStudyFlags(CLI::App& simulate, PivotStudyFlags& flags) {
  simulate.add_flag("--pivot", flags.pivot,
                    "The pivot study: synthetic tool-tip pivots calibrated as hecal pivot does "
                    "(docs/pivot.md)");
  simulate
      .add_option("--max-tilt", flags.max_tilt,
                  "With --pivot: orientations within +- this many degrees about each flange axis")
      ->capture_default_str();
  simulate.add_option("--write-pivot", flags.write_pivot,
                      "With --pivot: write the first trial's robot poses (mm) to this pose file");
}

void RunSimulatePivot(const PivotStudyInput& input, const PivotStudyFlags& flags, const Io& io) {
  jobs::PivotStudyOptions options;
  if (input.sigma_given) options.sigmas = input.simulate.sigmas;
  if (input.stations_given) options.stations = input.simulate.stations;
  if (input.trials_given) options.trials = input.simulate.trials;
  options.seed = input.simulate.seed;
  options.max_tilt_deg = flags.max_tilt;
  RequireValid(options);
  io::CheckOutputs({{"--write-pivot", flags.write_pivot}}, {});
  const jobs::PivotStudy study = jobs::RunPivotStudy(options);
  if (!flags.write_pivot.empty()) {
    io::WriteFilesAtomically({{"--write-pivot", flags.write_pivot, PivotPoseFile(options)}});
  }
  PrintPivotStudy(study, io);
  if (!flags.write_pivot.empty()) {
    io.out << "hecal: wrote the first trial's poses to " << flags.write_pivot << "\n";
  }
}

}  // namespace hecal::cli
