// `hecal pose`: see pose.h.
#include "pose.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <iomanip>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <string_view>
#include <vector>

#include "bounds.h"
#include "hecal/core/error.h"
#include "hecal/geometry/so3.h"
#include "hecal/io/atomic_file.h"
#include "hecal/io/camera_file.h"
#include "hecal/io/delimited_text.h"
#include "hecal/io/point_file.h"
#include "hecal/io/units.h"
#include "hecal/pose/pose_method.h"
#include "hecal/report/pose_file.h"
#if defined(HECAL_HAVE_OPENCV_PEERS)
#include "hecal/vision/opencv_pnp.h"
#endif

namespace hecal::cli {
namespace {

constexpr double kDegrees = 180.0 / std::numbers::pi;

// ---- pairing and the camera --------------------------------------------------------------------

struct Correspondences {
  std::vector<Eigen::Vector3d> object;  // metres
  std::vector<Eigen::Vector2d> pixels;
  std::vector<const io::PointRow*> image_rows;  // the image row of each pair (id, line)
};

Correspondences Pair(const io::PointFile& object, const io::PointFile& image) {
  Correspondences pairs;
  const auto add = [&](const io::PointRow& o, const io::PointRow& i) {
    pairs.object.push_back(o.value);
    pairs.pixels.push_back(i.value.head<2>());
    pairs.image_rows.push_back(&i);
  };
  if (object.has_ids && image.has_ids) {
    std::map<std::string, const io::PointRow*> by_id;
    for (const io::PointRow& row : object.rows) by_id.emplace(*row.id, &row);
    for (const io::PointRow& row : image.rows) {
      const auto it = by_id.find(*row.id);
      if (it == by_id.end()) {
        throw InputError(image.source, row.line,
                         "image point id '" + *row.id + "' is not in " + object.source,
                         "use the ids of the object points (or remove the id columns to pair by "
                         "order)");
      }
      add(*it->second, row);
    }
    return pairs;
  }
  if (object.rows.size() != image.rows.size()) {
    throw InputError(
        image.source, 0,
        std::to_string(image.rows.size()) + " image points but " +
            std::to_string(object.rows.size()) + " object points in " + object.source +
            " (paired by order: " +
            (object.has_ids || image.has_ids ? "only one file has ids" : "neither file has ids") +
            ")",
        "give one image point per object point in the same order, or ids in both "
        "files");
  }
  for (std::size_t k = 0; k < object.rows.size(); ++k) add(object.rows[k], image.rows[k]);
  return pairs;
}

double ParsePositive(const std::string& flag, const std::string& text, std::string_view what) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value) ||
      !(value > 0.0)) {
    throw InputError(flag, 0, "expected a positive number, got '" + text + "'",
                     "give " + std::string(what));
  }
  return value;
}

// The camera of --intrinsics (its notes printed to io.out) or of --focal / --principal-point.
pose::CameraModel Camera(const PoseCommandOptions& options, const Io& io) {
  if (options.intrinsics.empty() == options.focal.empty()) {
    throw InputError("--focal", 0, "give exactly one of --focal and --intrinsics",
                     "--intrinsics camera.yaml for a calibrated camera, or --focal F (px) for "
                     "the linear pose paper's pinhole without distortion");
  }
  if (!options.intrinsics.empty()) {
    if (!options.principal_point.empty()) {
      throw InputError("--principal-point", 0, "the principal point comes from --intrinsics",
                       "drop --principal-point");
    }
    const io::CameraFile file = io::ReadCameraFile(options.intrinsics);
    for (const std::string& note : file.notes) io.out << "note: " << note << "\n";
    return file.camera;
  }
  pose::CameraModel camera =
      pose::CameraModel::Pinhole(ParsePositive("--focal", options.focal, "the focal length in px"));
  if (!options.principal_point.empty()) {
    const std::size_t comma = options.principal_point.find(',');
    double c[2] = {0.0, 0.0};
    bool ok = comma != std::string::npos;
    for (int k = 0; ok && k < 2; ++k) {
      const std::string part = k == 0 ? options.principal_point.substr(0, comma)
                                      : options.principal_point.substr(comma + 1);
      const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), c[k]);
      ok = error == std::errc() && end == part.data() + part.size() && std::isfinite(c[k]);
    }
    if (!ok) {
      throw InputError("--principal-point", 0,
                       "expected two numbers CX,CY, got '" + options.principal_point + "'",
                       "write e.g. --principal-point 640,480 (pixels)");
    }
    camera.cx = c[0];
    camera.cy = c[1];
  }
  return camera;
}

// Every pixel must have a ray in this camera (strong distortion folds far outside the image).
void CheckRays(const Correspondences& pairs, const pose::CameraModel& camera,
               const std::string& source) {
  for (std::size_t k = 0; k < pairs.pixels.size(); ++k) {
    if (!pose::Undistort(camera, pairs.pixels[k])) {
      throw InputError(source, pairs.image_rows[k]->line,
                       "this pixel cannot be undistorted: the camera's distortion model has no "
                       "physical ray there",
                       "check the intrinsics (distortion coefficients) or remove the point");
    }
  }
}

// ---- methods -----------------------------------------------------------------------------------

std::string MethodList() {
  std::string names;
  for (const pose::PoseMethodInfo& info : pose::PoseMethods()) {
    names += (names.empty() ? "" : ", ") + std::string(info.name);
  }
#if defined(HECAL_HAVE_OPENCV_PEERS)
  for (const vision::PnpMethodInfo& info : vision::OpenCvPnpMethods()) {
    names += ", " + std::string(info.name);
  }
#endif
  return names;
}

pose::PoseEstimate Solve(const std::string& method, const Correspondences& pairs,
                         const pose::CameraModel& camera, const pose::PoseOptions& options) {
  if (const std::optional<pose::PoseMethod> core = pose::ParsePoseMethod(method)) {
    return pose::EstimatePose(*core, pairs.object, pairs.pixels, camera, options);
  }
#if defined(HECAL_HAVE_OPENCV_PEERS)
  if (const std::optional<vision::PnpMethod> peer = vision::ParsePnpMethod(method)) {
    const Pose T = vision::SolvePnPOpenCv(*peer, pairs.object, pairs.pixels, camera);
    return pose::FinishPose(method, T, *peer == vision::PnpMethod::kIterative, pairs.object,
                            pairs.pixels, camera, options.refinement);
  }
#else
  constexpr std::array<std::string_view, 4> kVisionMethods = {"ippe", "sqpnp", "epnp", "iterative"};
  if (std::find(kVisionMethods.begin(), kVisionMethods.end(), method) != kVisionMethods.end()) {
    throw InputError("--method", 0, "--method " + method + " needs the vision layer (OpenCV)",
                     "rebuild with -DHECAL_BUILD_VISION=ON, or use one of " + MethodList());
  }
#endif
  throw InputError("--method", 0, "unknown method '" + method + "'", "use one of " + MethodList());
}

// ---- output ------------------------------------------------------------------------------------

void Print(std::ostream& out, const pose::PoseEstimate& estimate, const Correspondences& pairs,
           io::LengthUnit unit) {
  const double scale = 1.0 / io::MetresPer(unit);
  const std::string_view unit_name = io::UnitName(unit);
  const Pose& T = estimate.T_camera_target;
  const Eigen::Vector3d rvec = so3::Log(T.linear());
  out << std::setprecision(6) << std::fixed;
  out << "method " << estimate.method << " (" << pairs.object.size() << " points)\n";
  out << "T_camera_target (x_camera = R x_target + t)\n";
  for (int r = 0; r < 3; ++r) {
    out << "  [";
    for (int c = 0; c < 3; ++c) out << std::setw(11) << T.linear()(r, c);
    out << " |" << std::setw(12) << T.translation()(r) * scale << " ]\n";
  }
  out << "  t = (" << (T.translation() * scale).transpose() << ") " << unit_name << "\n";
  out << "  rvec = (" << rvec.transpose() << ") rad, " << rvec.norm() * kDegrees << " deg\n";
  if (estimate.covariance) {
    const Vector6d sd = estimate.covariance->diagonal().cwiseSqrt();
    out << "  1σ rotation (rx, ry, rz) = (" << sd.head<3>().transpose() * kDegrees << ") deg\n";
    out << "  1σ translation (tx, ty, tz) = (" << sd.tail<3>().transpose() * scale << ") "
        << unit_name << "\n";
  }
  out << std::setprecision(4) << "reprojection RMS " << estimate.rms_px << " px per point";
  if (estimate.covariance) {
    out << ", pixel σ " << estimate.sigma_px << " px per axis ("
        << (estimate.sigma_source == pose::SigmaSource::kGiven ? "given"
                                                               : "estimated from the residuals")
        << ")";
  } else {
    out << " (no covariance: " << estimate.method << " is not refined)";
  }
  out << "\n";
  out.unsetf(std::ios::floatfield);
}

}  // namespace

void RunPose(const PoseCommandOptions& options, const Io& io) {
  const std::optional<io::LengthUnit> unit = io::ParseLengthUnit(options.units);
  if (!unit) throw InputError("--units", 0, "unknown unit '" + options.units + "'", "use m or mm");
  pose::PoseOptions pose_options;
  if (!options.pixel_sigma.empty()) {
    pose_options.refinement.pixel_sigma =
        ParsePositive("--pixel-sigma", options.pixel_sigma, "the pixel noise σ in px");
    CheckPixelSigma("--pixel-sigma", *pose_options.refinement.pixel_sigma);
  }
  io::CheckOutputs({{"--output", options.output}}, {{"--points", options.points},
                                                    {"--image-points", options.image_points},
                                                    {"--intrinsics", options.intrinsics}});
  const pose::CameraModel camera = Camera(options, io);

  constexpr std::array<std::string_view, 3> kObjectColumns = {"x", "y", "z"};
  constexpr std::array<std::string_view, 2> kImageColumns = {"u", "v"};
  const io::PointFile object =
      io::ReadPointFile(options.points, kObjectColumns, true, *unit, "object points");
  const io::PointFile image = io::ReadPointFile(options.image_points, kImageColumns, false,
                                                io::LengthUnit::kMetre, "image points");
  const Correspondences pairs = Pair(object, image);
  CheckRays(pairs, camera, image.source);

  const pose::PoseEstimate estimate = Solve(options.method, pairs, camera, pose_options);
  for (const std::string& warning : estimate.warnings)
    io.err << "hecal: warning: " << warning << "\n";
  Print(io.out, estimate, pairs, object.unit);
  if (!options.output.empty()) {
    std::vector<std::optional<std::string>> point_ids;
    for (const io::PointRow* row : pairs.image_rows) point_ids.push_back(row->id);
    io::WriteFileAtomically(options.output,
                            report::PoseResultJson(estimate, point_ids, object.unit));
    io.out << "wrote " << options.output << "\n";
  }
}

void RegisterPoseCommand(CLI::App& app, const Io& io) {
  auto options = std::make_shared<PoseCommandOptions>();
  CLI::App* command = app.add_subcommand(
      "pose", "Camera pose T_camera_target from known object points and their pixels");
  command->add_option("--points", options->points, "Object points: CSV id,x,y,z (target frame)")
      ->required();
  command->add_option("--image-points", options->image_points, "Image points: CSV id,u,v (px)")
      ->required();
  command->add_option(
      "--focal", options->focal,
      "Focal length F (px) of a distortion-free pinhole (docs/pose-from-points.md)");
  command->add_option("--principal-point", options->principal_point,
                      "CX,CY (px) with --focal (default 0,0)");
  command->add_option(
      "--intrinsics", options->intrinsics,
      "camera.yaml (hecal, OpenCV or ROS layout; plumb_bob distortion) or ViSP camera "
      "XML");
  command->add_option("--method", options->method, "Method (default linear): " + MethodList());
  command->add_option("--pixel-sigma", options->pixel_sigma,
                      "Pixel noise σ (px) for the covariance (default: from the residuals)");
  command->add_option("--units", options->units,
                      "Length unit of object columns without a suffix: m (default) or mm");
  command->add_option("--output", options->output, "Result JSON (written atomically)");
  std::string footer = "Methods:\n";
  for (const pose::PoseMethodInfo& info : pose::PoseMethods()) {
    footer += "  " + std::string(info.name) + ": " + std::string(info.summary) + "\n";
  }
#if defined(HECAL_HAVE_OPENCV_PEERS)
  for (const vision::PnpMethodInfo& info : vision::OpenCvPnpMethods()) {
    footer +=
        "  " + std::string(info.name) + ": " + std::string(info.summary) +
        (info.method == vision::PnpMethod::kIterative ? " (+ hecal refinement for the covariance)\n"
                                                      : " (no covariance)\n");
  }
#endif
  footer +=
      "Pairing: by id when both files have an id column, else by order.\n"
      "Output: R, t (object file's unit), rotation vector, 1σ per component (refined methods:\n"
      "  right perturbation, (rx,ry,rz,tx,ty,tz)), RMS reprojection error (px).";
  command->footer(footer);
  command->callback([options, io] { RunPose(*options, io); });
}

}  // namespace hecal::cli
