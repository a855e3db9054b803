// `hecal detect`: see detect.h.
#include "detect.h"

#include <CLI/CLI.hpp>
#include <memory>

#include "bounds.h"
#include "hecal/hecal.h"

#if defined(HECAL_HAVE_OPENCV_PEERS)
#include <vector>

#include "job_output.h"
#endif

namespace hecal::cli {

#if defined(HECAL_HAVE_OPENCV_PEERS)
void RunDetect(const DetectFlags& flags, const Io& io) {
  jobs::PoseDetectionOptions options;
  options.images = {flags.images, flags.target, flags.intrinsics, flags.threads,
                    vision::ImageUse::kPoses};
  options.output = flags.output;
  // The options first, then every output, before the detection; written all or none after it.
  RequireValid(options);
  const io::DetectionOutputPaths paths = io::DetectionCompanionPaths(flags.output);
  const std::string camera_path = flags.intrinsics.empty() ? paths.camera : "";
  io::CheckOutputs({{"--output", flags.output},
                    {"--output (points)", paths.points},
                    {"--output (intrinsics)", camera_path},
                    {"--report", flags.report}},
                   {{"--target", flags.target}, {"--intrinsics", flags.intrinsics}});
  const jobs::PoseDetection result = jobs::DetectCameraPoses(options, PrintingCallbacks(io));

  std::vector<io::OutputFile> outputs = {
      {"--output", flags.output, io::FormatPoseTable(result.table, result.write)},
      {"--output (points)", paths.points, io::FormatDetectedPoints(result.points)}};
  if (result.camera_yaml) {
    outputs.push_back({"--output (intrinsics)", camera_path, *result.camera_yaml});
  }
  if (!flags.report.empty()) {
    outputs.push_back({"--report", flags.report,
                       jobs::FormatDetectionReport(result.set, flags.images, flags.intrinsics)});
  }
  io::WriteFilesAtomically(outputs);
  io.out << "hecal: wrote " << result.table.rows.size() << " poses to " << flags.output
         << " (T_camera_target, m, quaternion), points to " << paths.points
         << (result.camera_yaml ? ", intrinsics to " + paths.camera : std::string())
         << (flags.report.empty() ? std::string() : ", the page to " + flags.report) << "\n";
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
  command->add_option("--report", flags->report,
                      "Interactive HTML page of the detections (docs/report.md), e.g. "
                      "detect.html: corners, residuals, coverage, thumbnails, camera poses");
  AddWholeNumber(*command, "--threads", flags->threads,
                 "Detection threads, 0 to 256 (default 0 = every core)");
  command->callback([flags, &io] { RunDetect(*flags, io); });
}

}  // namespace hecal::cli
