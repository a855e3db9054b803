// The stream study: stream_study.h (docs/streams.md#the-study).
#include "hecal/jobs/stream_study.h"

#include <atomic>
#include <cmath>
#include <cstdio>
#include <random>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/core/random_draws.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/geometry/so3.h"

namespace hecal::jobs {
namespace {

struct Errors {
  double rotation_deg = 0.0;
  double translation_mm = 0.0;
};

Errors ErrorOf(const Pose& estimate, const Pose& truth) {
  return {so3::Log(truth.linear().transpose() * estimate.linear()).norm() * kDegreesPerRadian,
          (estimate.translation() - truth.translation()).norm() * 1e3};
}

streams::PoseStream Stream(const std::vector<double>& stamps, const std::vector<Pose>& poses,
                           const char* name) {
  return {.stamps = stamps, .poses = poses, .lines = {}, .ids = {}, .source = name};
}

study::Setting SettingOf(const StreamStudyOptions& options, handeye::Setup setup,
                         const study::NoiseLevel& level) {
  study::Setting setting;
  setting.setup = setup;
  setting.noise_kind = options.noise;
  setting.translation_sigma = level.mm * 1e-3;
  setting.rotation_sigma = level.deg / kDegreesPerRadian;
  return setting;
}

StreamTrial RunTrial(const StreamStudyOptions& options, handeye::Setup setup,
                     const study::NoiseLevel& level, int trial) {
  const study::Setting setting = SettingOf(options, setup, level);
  const sim::SimulatedStreams data = SimulateStreamTrial(options, setup, level, trial);
  StreamTrial out;
  out.setup = setup;
  out.sigma = level;
  out.trial = trial;
  out.true_offset = data.time_offset;
  PoseCalibrationOptions calibration;
  calibration.setup = setup;
  if (!options.estimate_noise) {
    calibration.calibrate.robot_sigma = study::RobotSigma(setting);
    calibration.calibrate.camera_sigma = study::CameraSigma(setting);
  }
  calibration.calibrate.model_check = false;
  calibration.calibrate.covariance.threads = 1;
  const streams::PoseStream robot = Stream(data.robot_stamps, data.T_base_gripper, "robot");
  const streams::PoseStream camera = Stream(data.camera_stamps, data.T_camera_target, "camera");
  try {
    const report::ResultDocument document =
        CalibrateStreams(robot, camera, options.streams, calibration);
    const report::StreamReport& streams = *document.streams;
    out.offset_error = streams.offset - data.time_offset;
    out.offset_sigma = streams.offset_sigma.value_or(0.0);
    out.stations = static_cast<int>(document.results[0].residuals.size());
    const Errors stream = ErrorOf(document.results[0].X, data.X);
    out.rotation_error = stream.rotation_deg;
    out.translation_error = stream.translation_mm;
    // The same camera samples, perfectly paired.
    streams::StationRules rules = options.streams.rules;
    rules.margin = 0.0;
    const streams::StreamStations chosen =
        streams::ChooseStations(robot, camera, data.time_offset, rules);
    std::vector<Pose> A, B;
    for (const size_t k : chosen.samples) {
      A.push_back(data.perfectly_paired[k]);
      B.push_back(data.T_camera_target[k]);
    }
    const Errors paired = ErrorOf(CalibratePoses(A, B, calibration).document.results[0].X, data.X);
    out.paired_rotation_error = paired.rotation_deg;
    out.paired_translation_error = paired.translation_mm;
  } catch (const std::runtime_error& error) {  // InputError, DegenerateError
    out.failure = error.what();
  }
  return out;
}

double Rms(double sum_squares, int n) {
  return n > 0 ? std::sqrt(sum_squares / n) : 0.0;
}

}  // namespace

sim::SimulatedStreams SimulateStreamTrial(const StreamStudyOptions& options, handeye::Setup setup,
                                          const study::NoiseLevel& level, int trial) {
  const study::Setting setting = SettingOf(options, setup, level);
  std::mt19937_64 rng(study::TrialSeed(options.seed, setup, 0, trial));
  hecal::UniformRealDistribution offset(-options.offset_range, options.offset_range);
  sim::StreamSimulationOptions simulation = options.simulation;
  simulation.protocol.setup = setup;
  simulation.time_offset = offset(rng);
  return sim::SimulateStreams(simulation, study::RobotNoise(setting), study::CameraNoise(setting),
                              rng);
}

bool StreamStudyOptions::IsValid(std::string* why) const {
  if (setups.empty() || sigmas.empty()) {
    return Invalid(why, "StreamStudyOptions.setups", "needs at least one setup and noise level",
                   "give --setup and --sigma");
  }
  if (trials < 1 || trials > 100000) {
    return Invalid(why, "StreamStudyOptions.trials", "must be 1 … 100000",
                   "give the number of simulated recordings per setting (default 200)");
  }
  if (threads < 0 || threads > 256) {
    return Invalid(why, "StreamStudyOptions.threads", "must be 0 … 256", "0 uses every core");
  }
  if (!(offset_range >= 0.0 && offset_range <= 1.0)) {
    return Invalid(why, "StreamStudyOptions.offset_range", "must be 0 … 1 s",
                   "give the largest clock offset to simulate, in seconds (default 0.2)");
  }
  return simulation.IsValid(why) && streams.IsValid(why);
}

StreamStudyResult RunStreamStudy(const StreamStudyOptions& options) {
  RequireValid(options);
  StreamStudyResult result{.options = options, .trials = {}, .settings = {}};
  struct Job {
    handeye::Setup setup;
    study::NoiseLevel level;
    int trial;
  };
  std::vector<Job> jobs;
  for (const handeye::Setup setup : options.setups)
    for (const study::NoiseLevel& level : options.sigmas)
      for (int trial = 0; trial < options.trials; ++trial) jobs.push_back({setup, level, trial});
  result.trials.resize(jobs.size());
  std::atomic<size_t> next{0};
  const auto work = [&] {
    for (size_t k = next++; k < jobs.size(); k = next++)
      result.trials[k] = RunTrial(options, jobs[k].setup, jobs[k].level, jobs[k].trial);
  };
  const unsigned threads = options.threads > 0 ? static_cast<unsigned>(options.threads)
                                               : std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (std::thread& thread : pool) thread.join();

  for (size_t begin = 0; begin < jobs.size(); begin += static_cast<size_t>(options.trials)) {
    StreamSetting setting;
    setting.setup = jobs[begin].setup;
    setting.sigma = jobs[begin].level;
    double offset2 = 0, rotation2 = 0, translation2 = 0, paired_rotation2 = 0,
           paired_translation2 = 0, nees = 0;
    int within = 0, with_sigma = 0;
    for (size_t k = begin; k < begin + static_cast<size_t>(options.trials); ++k) {
      const StreamTrial& t = result.trials[k];
      ++setting.trials;
      if (!t.failure.empty()) {
        ++setting.failures;
        continue;
      }
      offset2 += t.offset_error * t.offset_error;
      setting.offset_max_ms = std::max(setting.offset_max_ms, std::abs(t.offset_error) * 1e3);
      if (t.offset_sigma > 0) {
        const double z = t.offset_error / t.offset_sigma;
        nees += z * z;
        within += std::abs(z) <= 1.96 ? 1 : 0;
        ++with_sigma;
      }
      rotation2 += t.rotation_error * t.rotation_error;
      translation2 += t.translation_error * t.translation_error;
      paired_rotation2 += t.paired_rotation_error * t.paired_rotation_error;
      paired_translation2 += t.paired_translation_error * t.paired_translation_error;
    }
    const int n = setting.trials - setting.failures;
    setting.offset_rms_ms = Rms(offset2, n) * 1e3;
    setting.offset_nees = with_sigma > 0 ? nees / with_sigma : 0.0;
    setting.offset_within_95 = with_sigma > 0 ? static_cast<double>(within) / with_sigma : 0.0;
    setting.rotation_rmse = Rms(rotation2, n);
    setting.translation_rmse = Rms(translation2, n);
    setting.paired_rotation_rmse = Rms(paired_rotation2, n);
    setting.paired_translation_rmse = Rms(paired_translation2, n);
    result.settings.push_back(setting);
  }
  return result;
}

std::string StreamTrialsCsv(const StreamStudyResult& result) {
  std::ostringstream out;
  out << "setup,sigma_mm,sigma_deg,trial,true_offset_s,offset_error_s,offset_sigma_s,stations,"
         "rotation_error_deg,translation_error_mm,paired_rotation_error_deg,"
         "paired_translation_error_mm,failure\n";
  out.precision(9);
  for (const StreamTrial& t : result.trials) {
    std::string failure = t.failure;
    for (char& c : failure)
      if (c == ',' || c == '\n' || c == '"') c = ' ';
    out << handeye::SetupName(t.setup) << ',' << t.sigma.mm << ',' << t.sigma.deg << ',' << t.trial
        << ',' << t.true_offset << ',' << t.offset_error << ',' << t.offset_sigma << ','
        << t.stations << ',' << t.rotation_error << ',' << t.translation_error << ','
        << t.paired_rotation_error << ',' << t.paired_translation_error << ',' << failure << '\n';
  }
  return out.str();
}

std::string StreamStudyText(const StreamStudyResult& result) {
  std::ostringstream out;
  const StreamStudyOptions& o = result.options;
  char line[400];
  std::snprintf(line, sizeof line,
                "Streams: robot %g Hz, camera %g Hz, %g s, offsets in ±%g ms; %d trials per "
                "setting, seed %llu\n",
                o.simulation.robot_rate, o.simulation.camera_rate, o.simulation.duration,
                o.offset_range * 1e3, o.trials, static_cast<unsigned long long>(o.seed));
  out << line;
  out << "setup        sigma (mm/deg)  fail  offset RMS  max     NEES   in 95%  "
         "X from streams (deg/mm)  perfectly paired (deg/mm)  ratio (rot/trans)\n";
  for (const StreamSetting& s : result.settings) {
    std::snprintf(
        line, sizeof line,
        "%-12s %5g/%-8g %5d  %7.3f ms  %6.2f  %5.2f  %5.1f%%  %9.4f / %-9.4f      "
        "%9.4f / %-9.4f         %5.2f / %5.2f\n",
        std::string(handeye::SetupName(s.setup)).c_str(), s.sigma.mm, s.sigma.deg, s.failures,
        s.offset_rms_ms, s.offset_max_ms, s.offset_nees, 100.0 * s.offset_within_95,
        s.rotation_rmse, s.translation_rmse, s.paired_rotation_rmse, s.paired_translation_rmse,
        s.paired_rotation_rmse > 0 ? s.rotation_rmse / s.paired_rotation_rmse : 0.0,
        s.paired_translation_rmse > 0 ? s.translation_rmse / s.paired_translation_rmse : 0.0);
    out << line;
  }
  return out.str();
}

}  // namespace hecal::jobs
