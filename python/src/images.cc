// From images (docs/python.md#from-images): hecal.calibrate_images (`hecal calibrate --images`,
// jobs::CalibrateFromImageFolder) and hecal.detect (`hecal detect`, jobs::DetectCameraPoses).
// Present when the library is built with its vision layer (HECAL_HAVE_VISION). Progress, notes
// and warnings go to the optional `log(kind, text)` callable (kind "progress", "note" or
// "warning"; called with the GIL held, possibly from a worker thread); silent by default. The GIL
// is released while the job runs.
#include <string>

#include "bindings.h"

namespace hecal::python {

#if defined(HECAL_HAVE_VISION)
namespace {

jobs::JobCallbacks Callbacks(const py::object& log) {
  jobs::JobCallbacks callbacks;
  if (log.is_none()) return callbacks;
  auto call = [log](const char* kind) {
    return [log, kind](const std::string& text) {
      py::gil_scoped_acquire acquire;
      log(kind, text);
    };
  };
  callbacks.progress = call("progress");
  callbacks.note = call("note");
  callbacks.warning = call("warning");
  return callbacks;
}

py::dict CameraDict(const pose::CameraModel& camera) {
  py::dict d;
  d["fx"] = camera.fx;
  d["fy"] = camera.fy;
  d["cx"] = camera.cx;
  d["cy"] = camera.cy;
  d["width"] = camera.width;
  d["height"] = camera.height;
  d["distortion"] = py::make_tuple(camera.distortion[0], camera.distortion[1],
                                   camera.distortion[2], camera.distortion[3],
                                   camera.distortion[4]);
  return d;
}

std::string RequirePath(const py::handle& object, const std::string& argument) {
  const auto path = AsPath(object);
  if (!path) ThrowArgument(argument, "is not a path", "give a str or os.PathLike");
  return *path;
}

constexpr const char* kCalibrateImagesDoc = R"doc(calibrate_images(images, target, robot, setup=None, method="ml", intrinsics=None, ...) -> CalibrationResult

Calibrate from a folder of target images and the robot poses (`hecal calibrate --images`):
detection, intrinsics (estimated when not given), PnP, the pose-level calibration, then the
joint reprojection refinement of X, Z and the robot poses.

images      folder of target images, one per robot pose (paired by id, else sorted by name)
target      target description, target.yaml (docs/targets.md)
robot       robot poses T_base_gripper: a pose file (docs/pose-files.md)
setup       "eye-in-hand" | "eye-to-hand" | "auto" / None
intrinsics  camera.yaml or ViSP camera XML (estimated from the images when None)
pixel_sigma pixel noise per axis, px (estimated when None)
refine_intrinsics  refine the intrinsics with X and Z in the joint refinement
method, robot_sigma, camera_sigma, units, degrees, euler, robot_inverse, keep_outliers,
robust, covariance ("linear" or "montecarlo"), covariance_samples, seed, threads:
            as hecal.calibrate (the CLI's flags)
log         callable(kind, text) receiving progress, notes and warnings; silent when None

Returns a CalibrationResult (lengths in the robot file's unit); to_json() is the result file
of `hecal calibrate --images ... --output`, with its "images" section.)doc";

constexpr const char* kDetectDoc = R"doc(detect(images, target, intrinsics=None, threads=0, log=None) -> (poses, ids, camera)

Camera poses from a folder of target images (`hecal detect`).

Returns poses, an (N, 4, 4) array of T_camera_target (the target in the camera frame: x right,
y down, z forward; METRES), one per used image in file-name order; ids, the images' stems (or
sub-folder names); camera, the intrinsics used (given or estimated): dict fx, fy, cx, cy
(px), width, height, distortion (k1, k2, p1, p2, k3).)doc";

}  // namespace

void RegisterImages(py::module_& m) {
  m.def(
      "calibrate_images",
      [](py::handle images, py::handle target, py::handle robot, std::optional<std::string> setup,
         std::string method, py::handle intrinsics, std::optional<double> pixel_sigma,
         bool refine_intrinsics, py::handle robot_sigma, py::handle camera_sigma,
         std::optional<std::string> units, bool degrees, std::optional<std::string> euler,
         bool robot_inverse, bool keep_outliers, std::string robust,
         std::optional<std::string> covariance, int covariance_samples, std::uint64_t seed,
         int threads, py::object log) {
        if (method == "all") {
          ThrowArgument("method", "method=\"all\" is not available from images",
                        "run hecal.detect, then hecal.calibrate on the poses with method=\"all\"");
        }
        jobs::ImageFolderCalibrationOptions options;
        const std::string intrinsics_path =
            intrinsics.is_none() ? std::string() : RequirePath(intrinsics, "intrinsics");
        options.images = {RequirePath(images, "images"), RequirePath(target, "target"),
                          intrinsics_path, threads};
        options.robot = RequirePath(robot, "robot");
        options.robot_read.units =
            ParseUnitArgument("units", units).value_or(io::LengthUnit::kMetre);
        options.robot_read.degrees = degrees;
        options.robot_read.euler = ParseEulerArgument(euler);
        options.robot_read.invert = robot_inverse;
        options.setup = ParseSetupArgument(setup);
        options.calibration.calibrate =
            CalibrateOptionsFromArguments(method, robot_sigma, camera_sigma, keep_outliers, robust,
                                          covariance, covariance_samples, seed, threads);
        if (options.calibration.calibrate.covariance.method ==
            estimation::CovarianceMethod::kUnscented) {
          ThrowArgument("covariance",
                        "covariance=\"unscented\" is not available from images (its input is the "
                        "noise of every detected pixel)",
                        "use \"linear\" (the default) or \"montecarlo\"");
        }
        options.calibration.pixel_sigma = pixel_sigma;
        options.calibration.refine_intrinsics = refine_intrinsics;
        options.words = PythonWords();
        options.caller = "hecal.calibrate_images";
        const jobs::JobCallbacks callbacks = Callbacks(log);
        report::ResultDocument document;
        {
          py::gil_scoped_release release;
          document = jobs::CalibrateFromImageFolder(options, callbacks).document;
        }
        return WrapDocument(std::move(document));
      },
      py::arg("images"), py::arg("target"), py::arg("robot"), py::kw_only(),
      py::arg("setup") = py::none(), py::arg("method") = "ml",
      py::arg("intrinsics") = py::none(), py::arg("pixel_sigma") = py::none(),
      py::arg("refine_intrinsics") = false, py::arg("robot_sigma") = py::none(),
      py::arg("camera_sigma") = py::none(), py::arg("units") = py::none(),
      py::arg("degrees") = false, py::arg("euler") = py::none(),
      py::arg("robot_inverse") = false, py::arg("keep_outliers") = false,
      py::arg("robust") = "none", py::arg("covariance") = py::none(),
      py::arg("covariance_samples") = 5000, py::arg("seed") = 1, py::arg("threads") = 0,
      py::arg("log") = py::none(), kCalibrateImagesDoc);

  m.def(
      "detect",
      [](py::handle images, py::handle target, py::handle intrinsics, int threads,
         py::object log) {
        jobs::PoseDetectionOptions options;
        const std::string intrinsics_path =
            intrinsics.is_none() ? std::string() : RequirePath(intrinsics, "intrinsics");
        options.images = {RequirePath(images, "images"), RequirePath(target, "target"),
                          intrinsics_path, threads};
        options.output = "camera.csv";  // named in the table's '#' lines only
        options.caller = "hecal.detect";
        const jobs::JobCallbacks callbacks = Callbacks(log);
        jobs::PoseDetection detection;
        {
          py::gil_scoped_release release;
          detection = jobs::DetectCameraPoses(options, callbacks);
        }
        std::vector<Pose> poses;
        std::vector<std::string> ids;
        for (size_t i = 0; i < detection.table.rows.size(); ++i) {
          poses.push_back(detection.table.rows[i].pose);
          ids.push_back(detection.table.rows[i].id.value_or(std::to_string(i)));
        }
        return py::make_tuple(ArrayFromPoses(poses), ids, CameraDict(detection.camera));
      },
      py::arg("images"), py::arg("target"), py::kw_only(), py::arg("intrinsics") = py::none(),
      py::arg("threads") = 0, py::arg("log") = py::none(), kDetectDoc);
}
#else
void RegisterImages(py::module_&) {}  // the library was built without its vision layer
#endif

}  // namespace hecal::python
