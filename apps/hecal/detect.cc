// `hecal detect`: see detect.h.
#include "detect.h"

#include <CLI/CLI.hpp>
#include <memory>

#include "bounds.h"
#include "hecal/core/error.h"

#if defined(HECAL_HAVE_OPENCV_PEERS)
#include <optional>
#include <vector>

#include "hecal/core/options_check.h"
#include "hecal/io/atomic_file.h"
#include "hecal/io/camera_file.h"
#include "hecal/io/delimited_text.h"
#include "hecal/io/detection_output.h"
#include "hecal/io/pose_table.h"
#include "hecal/jobs/image_front_end.h"
#include "job_output.h"
#endif

namespace hecal::cli {

#if defined(HECAL_HAVE_OPENCV_PEERS)
void RunDetect(const DetectFlags& flags, const Io& io) {
  const vision::ImageSetOptions options{flags.images, flags.target, flags.intrinsics, flags.threads,
                                        vision::ImageUse::kPoses};
  RequireValid(options);
  // Every output is checked before the detection and written all or none after it.
  const io::DetectionOutputPaths paths = io::DetectionCompanionPaths(flags.output);
  const std::string camera_path = flags.intrinsics.empty() ? paths.camera : "";
  io::CheckOutputs({{"--output", flags.output},
                    {"--output (points)", paths.points},
                    {"--output (intrinsics)", camera_path}},
                   {{"--target", flags.target}, {"--intrinsics", flags.intrinsics}});
  const vision::ImageSet set = jobs::DetectImages(options, "hecal detect", PrintingCallbacks(io));

  io::PoseTable table;
  table.source = flags.output;
  std::vector<io::DetectedPoint> points;
  for (const vision::ImageRecord& image : set.images) {
    if (!image.used()) continue;
    io::PoseRow row;
    row.pose = image.pose->T_camera_target;
    row.id = image.id();
    table.rows.push_back(row);
    for (const vision::ImagePoint& p : image.detection.points) {
      points.push_back({image.id(), p.id, p.pixel});
    }
  }
  io::PoseWriteOptions write;
  write.comments = {
      "hecal detect: T_camera_target of each image (id = image file stem or sub-folder), metres",
      "images: " + flags.images + "; target: " + flags.target + " (" +
          vision::Describe(set.target) + ")",
      "intrinsics: " +
          (set.estimated ? "estimated from the images, " + paths.camera : flags.intrinsics)};
  const std::string pose_text = io::FormatPoseTable(table, write);
  const std::string points_text = io::FormatDetectedPoints(points);
  std::string camera_text;
  if (set.estimated) {
    camera_text = io::FormatCameraYaml(
        set.camera,
        {"estimated by hecal detect (cv::calibrateCamera) from " +
             std::to_string(set.estimated->view_rms_px.size()) + " images in " + flags.images +
             ", " + std::to_string(set.size.width) + "x" + std::to_string(set.size.height),
         "RMS reprojection error " + io::FormatDouble(set.estimated->rms_px) + " px"});
  }
  std::vector<io::OutputFile> outputs = {{"--output", flags.output, pose_text},
                                         {"--output (points)", paths.points, points_text}};
  if (set.estimated) outputs.push_back({"--output (intrinsics)", camera_path, camera_text});
  io::WriteFilesAtomically(outputs);
  io.out << "hecal: wrote " << table.rows.size() << " poses to " << flags.output
         << " (T_camera_target, m, quaternion), points to " << paths.points
         << (set.estimated ? ", intrinsics to " + paths.camera : std::string()) << "\n";
}

#else

void RunDetect(const DetectFlags&, const Io&) {
  throw InputError("hecal detect", 0, "this hecal was built without the vision layer (OpenCV)",
                   "rebuild with -DHECAL_BUILD_VISION=ON");
}

#endif

void RegisterDetectCommand(CLI::App& app, const Io& io) {
  auto flags = std::make_shared<DetectFlags>();
  CLI::App* command = app.add_subcommand(
      "detect", "Camera poses T_camera_target from images of a target (and the intrinsics)");
  command
      ->add_option("--images", flags->images,
                   "Folder of images (png, jpg, jpeg, bmp, tif, tiff), taken in file-name "
                   "order; or of sub-folders with one image each (station id = sub-folder)")
      ->required();
  command->add_option("--target", flags->target, "target.yaml describing the target")->required();
  command->add_option("--intrinsics", flags->intrinsics,
                      "camera.yaml or ViSP camera XML (then one image is enough); estimated from "
                      "at least 3 images when absent and written to <output stem>.camera.yaml");
  command
      ->add_option("--output", flags->output,
                   "Pose table of T_camera_target (CSV); also writes <output stem>.points.csv")
      ->required();
  AddWholeNumber(*command, "--threads", flags->threads,
                 "Detection threads, 0 to 256 (default 0 = every core)");
  command->callback([flags, &io] { RunDetect(*flags, io); });
}

}  // namespace hecal::cli
