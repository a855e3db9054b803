// Streams without a camera stream (image_stream_calibration.h).
#include "hecal/jobs/image_stream_calibration.h"

#include <algorithm>
#include <map>

#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/io/stamp_file.h"

namespace hecal::jobs {

bool ImageStreamCalibrationOptions::IsValid(std::string* why) const {
  StreamCalibrationOptions check = streams;
  check.files.camera = detection.images.images;  // the images stand for the camera table
  return check.IsValid(why) && detection.images.IsValid(why);
}

report::ResultDocument CalibrateFromImageStream(const ImageStreamCalibrationOptions& options,
                                                const JobCallbacks& callbacks) {
  RequireValid(options);
  const PoseDetection detection = DetectCameraPoses(options.detection, callbacks);
  std::map<std::string, double> sidecar;
  if (!options.stamps.empty()) sidecar = io::ReadStampFile(options.stamps);
  io::PoseTable camera = detection.table;
  camera.source = options.detection.images.images;
  for (io::PoseRow& row : camera.rows) {
    const std::string& id = *row.id;
    if (options.stamps.empty()) {
      row.stamp = io::StampFromFileName(id);
    } else if (const auto it = sidecar.find(id); it != sidecar.end()) {
      row.stamp = it->second;
    } else {
      throw InputError(options.stamps, 0, "has no stamp for the image " + id,
                       "add a row " + id + ",STAMP (seconds) for every image of the folder");
    }
  }
  std::stable_sort(camera.rows.begin(), camera.rows.end(),
                   [](const io::PoseRow& a, const io::PoseRow& b) { return *a.stamp < *b.stamp; });
  for (size_t k = 0; k < camera.rows.size(); ++k) camera.rows[k].line = static_cast<int>(k) + 1;
  StreamCalibrationOptions streams = options.streams;
  streams.files.camera = options.detection.images.images;
  return CalibrateFromStreamTables(
      streams, io::ReadPoseTable(streams.files.robot, streams.files.robot_read), camera);
}

}  // namespace hecal::jobs
