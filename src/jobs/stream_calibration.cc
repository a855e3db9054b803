// Calibration from two recorded streams: stream_calibration.h (docs/streams.md).
#include "hecal/jobs/stream_calibration.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/estimation/ml.h"
#include "hecal/handeye/problem.h"
#include "hecal/streams/time_offset.h"
#include "hecal/streams/time_offset_search.h"

namespace hecal::jobs {
namespace {

constexpr double kNanosecondStamps = 1e14;  // stamps above this are integer nanoseconds
constexpr double kOffsetTolerance = 1e-5;   // seconds, of the profile's minimum
constexpr int kRefitRounds = 3;             // step 5's rounds of outlier tests and δ̂

// Step 1: a table as a stream; `note` gets the nanosecond conversion when made.
streams::PoseStream StreamOf(const io::PoseTable& table, std::vector<std::string>* notes) {
  streams::PoseStream stream;
  stream.source = table.source;
  for (const io::PoseRow& row : table.rows) {
    if (!row.stamp) {
      throw InputError(table.source, row.line, "has no stamp",
                       "--streams needs a `stamp` column (seconds) on every row; `hecal import "
                       "--format ethz` writes one (docs/streams.md)");
    }
    stream.stamps.push_back(*row.stamp);
    stream.poses.push_back(row.pose);
    stream.lines.push_back(row.line);
    if (row.id) stream.ids.push_back(*row.id);
  }
  if (stream.ids.size() != stream.stamps.size()) stream.ids.clear();
  if (!stream.stamps.empty() && std::abs(stream.stamps.front()) > kNanosecondStamps) {
    for (double& t : stream.stamps) t *= 1e-9;
    notes->push_back(table.source + ": stamps above 1e14 read as integer nanoseconds");
  }
  streams::CheckStream(stream);
  return stream;
}

std::string StampId(double t) {
  char text[40];
  std::snprintf(text, sizeof text, "t=%.6f", t);
  return text;
}

// Step 3's stations as paired poses with ids: the sparser stream's sample ids, or its stamps.
io::Stations StationsAt(const streams::PoseStream& robot, const streams::PoseStream& camera,
                        const streams::StreamStations& chosen, double offset) {
  const streams::PairedStreamPoses poses = streams::PosesAt(robot, camera, chosen, offset);
  io::Stations stations{.robot = poses.T_base_gripper, .camera = poses.T_camera_target, .ids = {}};
  const streams::PoseStream& sparse = chosen.camera_gives_stations ? camera : robot;
  for (const size_t k : chosen.samples)
    stations.ids.push_back(k < sparse.ids.size() ? sparse.ids[k] : StampId(sparse.stamps[k]));
  return stations;
}

using CalibrateStations = std::function<report::ResultDocument(
    const io::Stations&, const estimation::CalibrateOptions&, bool all_methods)>;

std::string Count(int n, const char* what) {
  return std::to_string(n) + " " + what;
}

// The profile of time_offset.h on `used` stations with the noise model of `result`, warm-started
// from the last optimum.
struct ProfileOnStations {
  const streams::PoseStream& robot;
  const streams::PoseStream& camera;
  streams::StreamStations used;
  handeye::Setup setup;
  estimation::MlOptions ml;
  handeye::Solution last;

  streams::ProfilePoint operator()(double offset) {
    const streams::PairedStreamPoses poses = streams::PosesAt(robot, camera, used, offset);
    if (poses.T_base_gripper.empty()) {
      return {.cost = std::numeric_limits<double>::infinity(), .X = last.X, .Z = last.Z};
    }
    const handeye::Problem problem =
        handeye::MakeProblem(setup, poses.T_base_gripper, poses.T_camera_target);
    const estimation::MlResult fit = estimation::RefineMl(problem, {last}, ml);
    last = {.X = fit.X, .Z = fit.Z};
    return {.cost = fit.cost, .X = fit.X, .Z = fit.Z};
  }
};

// `drop_rejected`: profile on the stations `document` kept (else on every chosen station).
ProfileOnStations MakeProfile(const streams::PoseStream& robot, const streams::PoseStream& camera,
                              const streams::StreamStations& chosen,
                              const report::ResultDocument& document, bool drop_rejected = true) {
  const estimation::CalibrationResult& result = document.results.at(0);
  ProfileOnStations profile{.robot = robot,
                            .camera = camera,
                            .used = chosen,
                            .setup = document.setup,
                            .ml = {},
                            .last = {}};
  profile.used.samples.clear();
  for (size_t i = 0; i < chosen.samples.size(); ++i) {
    if (!drop_rejected || std::find(document.rejected.begin(), document.rejected.end(),
                                    static_cast<int>(i)) == document.rejected.end())
      profile.used.samples.push_back(chosen.samples[i]);
  }
  // A noise model that is exactly zero (noise-free data) would make the whitening singular.
  constexpr double kFloor = 1e-12;
  profile.ml.robot_sigma = estimation::PoseSigma{std::max(result.robot_sigma.rotation, kFloor),
                                                 std::max(result.robot_sigma.translation, kFloor)};
  profile.ml.camera_sigma =
      estimation::PoseSigma{std::max(result.camera_sigma.rotation, kFloor),
                            std::max(result.camera_sigma.translation, kFloor)};
  profile.ml.camera_excess = result.camera_excess;
  profile.ml.heavy_tails = false;
  profile.ml.starts_on_demand = false;
  profile.ml.max_noise_iterations = 1;
  profile.last = {.X = result.X, .Z = result.Z};
  return profile;
}

// Steps 2–5 of stream_calibration.h on checked streams; `calibrate` runs step 4 on paired
// stations.
report::ResultDocument FitStreams(const streams::PoseStream& robot,
                                  const streams::PoseStream& camera, const StreamOptions& options,
                                  const estimation::CalibrateOptions& calibrate_options,
                                  bool all_methods, const CalibrateStations& calibrate) {
  // Step 2.
  report::StreamReport report;
  report.robot_samples = static_cast<int>(robot.stamps.size());
  report.camera_samples = static_cast<int>(camera.stamps.size());
  report.search_window = options.window;
  report.offset_estimated = !options.time_offset;
  const double period = std::max(streams::MedianPeriod(robot), streams::MedianPeriod(camera));
  double max_gap = options.rules.max_gap;
  if (max_gap == 0.0) {
    max_gap = 3.0 * std::min(streams::MedianPeriod(robot), streams::MedianPeriod(camera));
  }
  double offset = options.time_offset.value_or(0.0);
  std::vector<std::string> warnings;
  if (!options.time_offset) {
    const streams::CoarseOffset coarse =
        streams::SearchTimeOffset(robot, camera, options.window, std::max(max_gap, 3 * period));
    if (coarse.found) {
      offset = coarse.offset;
      report.coarse_offset = coarse.offset;
      report.coarse_correlation = coarse.correlation;
    } else {
      report.offset_estimated = false;
      warnings.push_back(
          "the streams show no motion to tell the clocks' offset by: stations were paired at "
          "offset 0 (give --time-offset SECONDS when it is known)");
    }
  }

  // Step 3.
  // The scan's grid step: χ² is smooth over a few sample periods.
  const double grid = std::min(std::max(2.0 * period, 0.02), options.window);
  streams::StationRules rules = options.rules;
  // The fit may move the offset anywhere in the window: stations must have poses there.
  rules.margin = report.offset_estimated ? options.window + std::abs(offset) : 0.0;
  const streams::StreamStations chosen = streams::ChooseStations(robot, camera, offset, rules);
  report.camera_gives_stations = chosen.camera_gives_stations;
  report.max_gap = chosen.max_gap;
  report.smoothing = chosen.smoothing;
  report.max_angular_speed = rules.max_angular_speed;
  report.max_linear_speed = rules.max_linear_speed;
  report.max_stations = rules.max_stations;
  report.candidates = chosen.candidates;
  report.dropped_outside = chosen.dropped_outside;
  report.dropped_gap = chosen.dropped_gap;
  report.dropped_fast = chosen.dropped_fast;
  report.thinned = chosen.thinned;
  if (chosen.samples.size() < 3) {
    throw InputError(
        (chosen.camera_gives_stations ? camera : robot).source, 0,
        "only " + std::to_string(chosen.samples.size()) + " of its " +
            std::to_string(chosen.candidates) + " samples can be stations (" +
            Count(chosen.dropped_outside, "outside the other stream, ") +
            Count(chosen.dropped_gap, "at a gap longer than ") + std::to_string(chosen.max_gap) +
            " s, " + Count(chosen.dropped_fast, "in fast motion)"),
        "check that both streams cover the same time (the offset search is ±--time-offset-window), "
        "or relax --max-gap / --max-speed");
  }

  // Step 4. A given sigma of the denser stream is its noise per sample; its stations' poses are
  // the local regression's, less noisy by SmoothedNoiseFactor (about 0.5 at 50 Hz).
  report.smoothed_noise_factor = streams::SmoothedNoiseFactor(robot, camera, chosen, offset);
  estimation::CalibrateOptions at_stations = calibrate_options;
  std::optional<estimation::PoseSigma>& smoothed_sigma =
      chosen.camera_gives_stations ? at_stations.robot_sigma : at_stations.camera_sigma;
  if (smoothed_sigma) {
    smoothed_sigma->rotation *= report.smoothed_noise_factor;
    smoothed_sigma->translation *= report.smoothed_noise_factor;
  }
  const auto calibrate_at = [&](double at, const estimation::CalibrateOptions& with, bool all) {
    return calibrate(StationsAt(robot, camera, chosen, at), with, all);
  };
  // When the offset is fitted, this first calibration only gives the noise model and the
  // stations used: ml without covariance or model check.
  estimation::CalibrateOptions first = at_stations;
  if (report.offset_estimated) {
    first.method = estimation::Method::kMl;
    first.covariance.method = estimation::CovarianceMethod::kNone;
    first.model_check = false;
  }
  report::ResultDocument document =
      calibrate_at(offset, first, all_methods && !report.offset_estimated);

  // Step 5.
  if (report.offset_estimated) {
    // The scan over the whole window uses every chosen station: the first calibration's outlier
    // tests ran at the coarse offset, where the offset's error shows at the stations that move
    // fast, and kept the stations whose noise happened to hide it — a selection that pulls the
    // minimum back toward the coarse value (measured: 39 of 200 stations rejected 3.7 ms off,
    // and δ̂ off by 4 σ).
    ProfileOnStations search = MakeProfile(robot, camera, chosen, document, false);
    const streams::OffsetMinimum minimum = streams::MinimiseProfile(
        std::ref(search), offset, -options.window, options.window, grid, kOffsetTolerance);
    offset = minimum.offset;
    report.profile_evaluations = minimum.evaluations;
    if (minimum.on_edge) {
      warnings.push_back("the fitted time offset lies on the edge of the search window ±" +
                         std::to_string(options.window) +
                         " s: widen --time-offset-window, or check that the robot and camera "
                         "files are of the same recording");
    }
    // Then, until they agree: the noise model and the outlier tests at δ̂, and δ̂ again on the
    // stations kept, within one grid step.
    for (int round = 0; round < kRefitRounds; ++round) {
      document = calibrate_at(offset, first, false);
      ProfileOnStations kept = MakeProfile(robot, camera, chosen, document);
      const streams::OffsetMinimum again = streams::MinimiseProfile(
          std::ref(kept), offset, std::max(offset - grid, -options.window),
          std::min(offset + grid, options.window), grid / 2, kOffsetTolerance);
      report.profile_evaluations += again.evaluations;
      const bool settled = std::abs(again.offset - offset) < 2 * kOffsetTolerance;
      offset = again.offset;
      if (settled) break;
    }
    document = calibrate_at(offset, at_stations, all_methods);
    ProfileOnStations at_result = MakeProfile(robot, camera, chosen, document);
    const streams::ProfilePoint at = at_result(offset);
    const streams::OffsetUncertainty uncertainty =
        streams::ProfileUncertainty(std::ref(at_result), offset, at, 1e-3);
    if (uncertainty.curved) {
      report.offset_sigma = uncertainty.sigma;
      report.covariance_with_XZ = uncertainty.slope * uncertainty.sigma * uncertainty.sigma;
      for (estimation::CalibrationResult& result : document.results)
        if (result.covariance) result.covariance->covariance += uncertainty.added;
    } else {
      warnings.push_back(
          "the fit does not change with the time offset (too little motion at the stations): "
          "its σ is unknown and (X, Z)'s covariance leaves it out");
    }
  }
  report.offset = offset;
  for (estimation::CalibrationResult& result : document.results)
    result.warnings.insert(result.warnings.begin(), warnings.begin(), warnings.end());
  document.streams = report;
  return document;
}

}  // namespace

bool StreamCalibrationOptions::IsValid(std::string* why) const {
  return files.IsValid(why) && streams.IsValid(why);
}

bool StreamOptions::IsValid(std::string* why) const {
  if (time_offset && !std::isfinite(*time_offset)) {
    return Invalid(why, "StreamOptions.time_offset", "is not a finite number",
                   "give the offset in seconds (e.g. 0.03), or leave it out to estimate it");
  }
  if (!(window > 0.0) || !std::isfinite(window)) {
    return Invalid(why, "StreamOptions.window", "must be a finite number above 0",
                   "give the half-width of the offset search in seconds (default 1)");
  }
  if (!(rules.max_gap >= 0.0) || !std::isfinite(rules.max_gap)) {
    return Invalid(why, "StreamOptions.rules.max_gap", "must be 0 or a finite time",
                   "give the longest gap to interpolate across in seconds (0: 3 periods)");
  }
  if (!(rules.max_angular_speed > 0.0) || !(rules.max_linear_speed > 0.0)) {
    return Invalid(why, "StreamOptions.rules.max_angular_speed", "the speed limits must be above 0",
                   "give the fastest motion to take stations in, e.g. --max-speed 45,0.3");
  }
  if (rules.max_stations < 3) {
    return Invalid(why, "StreamOptions.rules.max_stations", "must be at least 3",
                   "give how many stations to keep at most (default 500)");
  }
  return true;
}

report::ResultDocument CalibrateFromStreams(const StreamCalibrationOptions& options) {
  RequireValid(options);
  const PoseFileCalibrationOptions& files = options.files;
  return CalibrateFromStreamTables(options, io::ReadPoseTable(files.robot, files.robot_read),
                                   io::ReadPoseTable(files.camera, files.camera_read));
}

report::ResultDocument CalibrateFromStreamTables(const StreamCalibrationOptions& options,
                                                 const io::PoseTable& robot_table,
                                                 const io::PoseTable& camera_table) {
  RequireValid(options);
  const PoseFileCalibrationOptions& files = options.files;
  std::vector<std::string> notes;
  const streams::PoseStream robot = StreamOf(robot_table, &notes);
  const streams::PoseStream camera = StreamOf(camera_table, &notes);
  return FitStreams(
      robot, camera, options.streams, files.calibrate, files.all_methods,
      [&](const io::Stations& stations, const estimation::CalibrateOptions& with, bool all) {
        PairedPoses poses = PairedTablePoses(files, robot_table, camera_table, stations);
        poses.notes.insert(poses.notes.begin(), notes.begin(), notes.end());
        return CalibratePairedPoses(poses, with, all).document;
      });
}

report::ResultDocument CalibrateStreams(const streams::PoseStream& robot,
                                        const streams::PoseStream& camera,
                                        const StreamOptions& options,
                                        const PoseCalibrationOptions& calibration) {
  RequireValid(calibration);
  RequireValid(options);
  streams::CheckStream(robot);
  streams::CheckStream(camera);
  return FitStreams(
      robot, camera, options, calibration.calibrate, calibration.all_methods,
      [&](const io::Stations& stations, const estimation::CalibrateOptions& with, bool all) {
        PoseCalibrationOptions at = calibration;
        at.calibrate = with;
        at.all_methods = all;
        at.station_ids = stations.ids;
        return CalibratePoses(stations.robot, stations.camera, at).document;
      });
}

}  // namespace hecal::jobs
