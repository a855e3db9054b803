// Calibration from two recorded streams (`hecal calibrate --streams`; docs/streams.md): a robot
// stream of T_base_gripper and a camera stream of T_camera_target, each a pose table with a
// `stamp` column on its own clock, at any rates.
//
// Steps (CalibrateFromStreams)
//   1. The options checked; both tables read (io/pose_table.h, each with its read options) and
//      every row must have a stamp. Stamps above 1e14 are taken as integer nanoseconds (ROS and
//      most loggers; 1e14 s would be three million years) and converted, with a note. The streams
//      checked (streams/pose_stream.h: at least 2 samples, finite, strictly increasing).
//   2. The coarse time offset (streams/time_offset_search.h, ±window), or the offset given.
//   3. Stations chosen at that offset (streams/stream_stations.h: the sparser stream's samples,
//      the denser smoothed at their times; never across a gap; not in fast motion; thinned to
//      max_stations well spread in rotation). Station ids: the sparser table's id, or its stamp.
//   4. Calibration at that offset as from paired pose files (pose_file_calibration.h steps 4–5:
//      the convention check, the method, outlier rejection, covariance). A given sigma of the
//      denser stream is its noise per sample: scaled by the smoothing's factor
//      (stream_stations.h SmoothedNoiseFactor) for its smoothed poses at the stations.
//   5. Unless the offset was given: the offset fitted jointly with X and Z (streams/time_offset.h)
//      with step 4's noise model on every station (not only those step 4 kept: its outlier tests
//      ran at the coarse offset, and keeping the stations whose noise hides the coarse offset's
//      error pulls the fit back toward it); then, until the offset moves by less than 2e-5 s
//      (at most 3 rounds), step 4 at the fitted offset (noise model, outlier tests) and the
//      offset again on the stations it kept, within one grid step; then step 4 at the final
//      offset, the offset's σ and its covariance with (X, Z) at that result's noise model;
//      (X, Z)'s covariance gains the offset's share (time_offset.h).
// The document's `streams` (report::StreamReport) says what was used and the offset.
//
// Errors: InputError for invalid options, a table without stamps, bad stamps, streams that do not
// overlap, too few stations left by the rules (naming how many each rule dropped); those of the
// tables, the convention check and the calibration pass through. Warnings (in the result): no
// motion to tell the offset (the offset is then 0 or the one given), a fitted offset on the edge
// of the window.
#pragma once

#include <optional>
#include <string>

#include "hecal/jobs/pose_calibration.h"
#include "hecal/jobs/pose_file_calibration.h"
#include "hecal/report/result_file.h"
#include "hecal/streams/stream_stations.h"

namespace hecal::jobs {

// How stations are made of the streams and whether the offset is fitted.
struct StreamOptions {
  std::optional<double> time_offset;  // seconds, given: not estimated (--time-offset)
  double window = 1.0;                // seconds, ± of the coarse search (--time-offset-window)
  streams::StationRules rules;        // --max-gap, --max-speed, --stations
  // core/options_check.h: false naming StreamOptions.time_offset (not finite), .window (not
  // above 0 and finite), .rules.max_gap (negative or not finite), .rules.max_angular_speed (a
  // speed limit not above 0), .rules.max_stations (below 3).
  bool IsValid(std::string* why) const;
};

struct StreamCalibrationOptions {
  PoseFileCalibrationOptions files;  // the two tables, their reading, setup, method, words
  StreamOptions streams;
  // files (PoseFileCalibrationOptions::IsValid), then streams.
  bool IsValid(std::string* why) const;
};

// Steps 1–5 from two pose tables.
report::ResultDocument CalibrateFromStreams(const StreamCalibrationOptions& options);

// The same from tables already read (options.files names them in messages): the camera stream of
// images (image_stream_calibration.h) comes this way.
report::ResultDocument CalibrateFromStreamTables(const StreamCalibrationOptions& options,
                                                 const io::PoseTable& robot,
                                                 const io::PoseTable& camera);

// Steps 1 (the stream check) to 5 from streams in memory (metres), step 4 as CalibratePoses
// (pose_calibration.h) does it with `calibration` (its station_ids are ignored: the sparser
// stream's ids, or its stamps, name the stations).
report::ResultDocument CalibrateStreams(const streams::PoseStream& robot,
                                        const streams::PoseStream& camera,
                                        const StreamOptions& options,
                                        const PoseCalibrationOptions& calibration);

}  // namespace hecal::jobs
