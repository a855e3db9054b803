// The stream study (`hecal simulate --streams`; docs/streams.md#the-study): simulated recordings
// (sim/stream_simulation.h) with a random clock offset, calibrated from the streams
// (stream_calibration.h), against the same camera samples perfectly paired.
//
// Per trial: the offset is drawn from U(−offset_range, offset_range); the streams simulated with
// the setting's noise on every sample (study/study.h's RobotNoise / CameraNoise: the thesis
// protocol's levels); CalibrateStreams with ml, told the setting's sigmas (or estimating them with
// estimate_noise), the offset fitted; then the perfectly paired data of the same camera samples —
// the stations ChooseStations picks at the true offset — calibrated with the same options. Each
// trial records the offset's error and reported σ, and X's rotation and translation error of both.
// Summary per setting: the offset's RMS error (ms), its NEES (mean of (error/σ)², which is 1 for
// an honest σ) with the fraction of trials inside ±1.96σ (95% expected), and X's RMSE from the
// streams over X's RMSE from perfectly paired data (1 when nothing is lost to the clocks).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "hecal/handeye/problem.h"
#include "hecal/jobs/stream_calibration.h"
#include "hecal/sim/stream_simulation.h"
#include "hecal/study/study.h"

namespace hecal::jobs {

struct StreamStudyOptions {
  std::vector<handeye::Setup> setups = {handeye::Setup::kEyeInHand};
  std::vector<study::NoiseLevel> sigmas = {{1.0, 0.1}};  // mm, deg per component
  sim::NoiseModel::Kind noise = sim::NoiseModel::Kind::kGaussian;
  int trials = 200;
  std::uint64_t seed = 1;
  int threads = 0;                          // 0: every core
  bool estimate_noise = false;              // tell no fit the sigmas
  double offset_range = 0.2;                // seconds: offsets drawn from U(−range, range)
  sim::StreamSimulationOptions simulation;  // rates, duration, motion (time_offset drawn)
  StreamOptions streams;                    // the stations' rules and the search window
  // core/options_check.h: false naming StreamStudyOptions.<field> (trials 1 … 100000, threads
  // 0 … 256, offset_range 0 … 1 s, no setups or sigmas) or a field of simulation or streams.
  bool IsValid(std::string* why) const;
};

struct StreamTrial {
  handeye::Setup setup = handeye::Setup::kEyeInHand;
  study::NoiseLevel sigma;
  int trial = 0;
  double true_offset = 0.0;            // seconds
  double offset_error = 0.0;           // fitted − true, seconds
  double offset_sigma = 0.0;           // reported, seconds (0: not reported)
  int stations = 0;                    // used by the stream fit
  double rotation_error = 0.0;         // X, degrees, from the streams
  double translation_error = 0.0;      // X, mm
  double paired_rotation_error = 0.0;  // X from the perfectly paired data
  double paired_translation_error = 0.0;
  std::string failure;  // non-empty: the fit threw this message (other fields unset)
};

struct StreamSetting {
  handeye::Setup setup = handeye::Setup::kEyeInHand;
  study::NoiseLevel sigma;
  int trials = 0;
  int failures = 0;
  double offset_rms_ms = 0.0;
  double offset_max_ms = 0.0;
  double offset_nees = 0.0;                            // mean (error / σ)²
  double offset_within_95 = 0.0;                       // fraction with |error| ≤ 1.96 σ
  double rotation_rmse = 0.0, translation_rmse = 0.0;  // deg, mm: from the streams
  double paired_rotation_rmse = 0.0, paired_translation_rmse = 0.0;
};

struct StreamStudyResult {
  StreamStudyOptions options;
  std::vector<StreamTrial> trials;  // setting-major, then trial
  std::vector<StreamSetting> settings;
};

// The recording of one trial (its offset drawn, then SimulateStreams), as RunStreamStudy makes it.
sim::SimulatedStreams SimulateStreamTrial(const StreamStudyOptions& options, handeye::Setup setup,
                                          const study::NoiseLevel& level, int trial);

// Throws hecal::InputError when !options.IsValid. Same seed, same result whatever `threads`.
StreamStudyResult RunStreamStudy(const StreamStudyOptions& options);

// The per-trial CSV and the summary table (text) of a study.
std::string StreamTrialsCsv(const StreamStudyResult& result);
std::string StreamStudyText(const StreamStudyResult& result);

}  // namespace hecal::jobs
