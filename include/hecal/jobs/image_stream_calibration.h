// Streams without a camera stream (`hecal calibrate --streams --images DIR [--stamps FILE]`,
// docs/streams.md#images-as-the-camera-stream): the camera poses detected in time-stamped images
// are the camera stream.
//
// Steps (CalibrateFromImageStream)
//   1. The options checked; the images detected and their poses estimated as `hecal detect`
//      does (pose_detection.h: target, intrinsics given or estimated, PnP per image).
//   2. Each image with a pose stamped: from the sidecar (io/stamp_file.h), or from its file name
//      when no sidecar is given. An image without a stamp stops the run naming it; a stamp
//      without an image is ignored (the sidecar may list images that were not kept).
//   3. The images sorted by stamp as the camera stream, then CalibrateFromStreamTables
//      (stream_calibration.h) with the robot stream.
// Errors: hecal::InputError (options, files, stamps, streams) and DegenerateError pass through.
#pragma once

#include <string>

#include "hecal/jobs/job_callbacks.h"
#include "hecal/jobs/pose_detection.h"
#include "hecal/jobs/stream_calibration.h"

namespace hecal::jobs {

struct ImageStreamCalibrationOptions {
  StreamCalibrationOptions streams;  // files.robot: the robot stream; files.camera is unused
  PoseDetectionOptions detection;    // the images, target, intrinsics, threads
  std::string stamps;                // the sidecar CSV; "" = stamps from the file names
  // streams.files without .camera, then detection.images (ImageSetOptions::IsValid).
  bool IsValid(std::string* why) const;
};

report::ResultDocument CalibrateFromImageStream(const ImageStreamCalibrationOptions& options,
                                                const JobCallbacks& callbacks);

}  // namespace hecal::jobs
