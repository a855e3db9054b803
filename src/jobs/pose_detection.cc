// Camera poses from a folder of target images: see pose_detection.h.
#include "hecal/jobs/pose_detection.h"

#include <utility>

#include "hecal/core/options_check.h"
#include "hecal/io/camera_file.h"
#include "hecal/io/delimited_text.h"
#include "hecal/jobs/image_front_end.h"

namespace hecal::jobs {

bool PoseDetectionOptions::IsValid(std::string* why) const {
  if (!images.IsValid(why)) return false;
  if (output.empty()) {
    return Invalid(why, "PoseDetectionOptions.output", "is empty",
                   "give the path of the pose table to write");
  }
  return true;
}

PoseDetection DetectCameraPoses(const PoseDetectionOptions& options,
                                const JobCallbacks& callbacks) {
  RequireValid(options);
  vision::ImageSetOptions image_options = options.images;
  image_options.use = vision::ImageUse::kPoses;
  vision::ImageSet set = DetectImages(image_options, options.caller, callbacks);

  PoseDetection result;
  result.camera = set.camera;
  result.table.source = options.output;
  for (const vision::ImageRecord& image : set.images) {
    if (!image.used()) continue;
    io::PoseRow row;
    row.pose = image.pose->T_camera_target;
    row.id = image.id();
    result.table.rows.push_back(row);
    for (const vision::ImagePoint& p : image.detection.points) {
      result.points.push_back({image.id(), p.id, p.pixel});
    }
  }
  const std::string& images = options.images.images;
  result.write.comments = {
      options.caller +
          ": T_camera_target of each image (id = image file stem or sub-folder), metres",
      "images: " + images + "; target: " + options.images.target + " (" +
          vision::Describe(set.target) + ")",
      "intrinsics: " + (set.estimated ? "estimated from the images, " +
                                            io::DetectionCompanionPaths(options.output).camera
                                      : options.images.intrinsics)};
  if (set.estimated) {
    result.camera_yaml = io::FormatCameraYaml(
        set.camera,
        {"estimated by " + options.caller + " (cv::calibrateCamera) from " +
             std::to_string(set.estimated->view_rms_px.size()) + " images in " + images + ", " +
             std::to_string(set.size.width) + "x" + std::to_string(set.size.height),
         "RMS reprojection error " + io::FormatDouble(set.estimated->rms_px) + " px"});
  }
  result.set = std::move(set);
  return result;
}

}  // namespace hecal::jobs
