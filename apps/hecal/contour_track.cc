// `hecal contour track` and `hecal contour render`: see contour_track.h.
#include "contour_track.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <numbers>
#include <optional>
#include <string_view>
#include <vector>

#include "bounds.h"
#include "contour.h"
#include "hecal/contour/affine_pose.h"
#include "hecal/contour/bspline.h"
#include "hecal/contour/contour_study.h"
#include "hecal/contour/pose_uncertainty.h"
#include "hecal/contour/render.h"
#include "hecal/contour/sequence.h"
#include "hecal/contour/shape_space.h"
#include "hecal/contour/shape_tracker.h"
#include "hecal/core/error.h"
#include "hecal/io/atomic_file.h"
#include "hecal/io/delimited_text.h"
#include "hecal/io/image_files.h"
#include "hecal/report/contour_track_file.h"
#include "hecal/version.h"
#if defined(HECAL_HAVE_OPENCV_PEERS)
#include "hecal/vision/contour_images.h"
#endif

namespace hecal::cli {
namespace {

namespace fs = std::filesystem;
constexpr double kDegrees = 180.0 / std::numbers::pi;

double ParsePositive(const std::string& flag, const std::string& text, const std::string& what) {
  const double value = ParseNumber(flag, text, what);
  if (!(value > 0.0)) {
    throw InputError(flag, 0, "must be positive, got '" + text + "'", "give " + what);
  }
  return value;
}

std::string Lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

#if !defined(HECAL_HAVE_OPENCV_PEERS)
[[noreturn]] void NeedsVision(const std::string& flag) {
  throw InputError(flag, 0, "reading and writing images needs the vision layer (OpenCV)",
                   "build hecal with HECAL_BUILD_VISION=ON");
}
#endif

// ---- track -------------------------------------------------------------------------------------

enum class OutputKind { kNone, kCsv, kJson };

OutputKind ParseOutputKind(const std::string& output) {
  if (output.empty()) return OutputKind::kNone;
  const std::string extension = Lower(fs::path(output).extension().string());
  if (extension == ".csv") return OutputKind::kCsv;
  if (extension == ".json") return OutputKind::kJson;
  throw InputError("--output", 0, "unknown output format '" + output + "'",
                   "name the file *.csv (one row per frame) or *.json (full covariances)");
}

// The pose model --pose-model selects (auto: perspective when the principal point is given).
bool UsesPerspectivePose(const ContourTrackOptions& options) {
  return options.pose_model == "perspective" ||
         (options.pose_model == "auto" && !options.principal_point.empty());
}

}  // namespace

void RunContourTrack(const ContourTrackOptions& options, const Io& io) {
  const contour::ContourCamera camera = ParseContourCamera(options.focal, options.z0);
  const std::optional<contour::RotationForm> form = contour::ParseRotationForm(options.rotation);
  if (!form) {
    throw InputError("--rotation", 0, "unknown rotation form '" + options.rotation + "'",
                     "use zyx (roll–pitch–yaw, the contour paper's choice) or zxz");
  }
  contour::ShapeTrackerOptions tracker_options;
  const std::optional<contour::ShapeSubspace> subspace =
      contour::ParseShapeSubspace(options.subspace);
  if (!subspace) {
    throw InputError("--subspace", 0, "unknown shape subspace '" + options.subspace + "'",
                     "use full, similarity, translation-scale, planar-robot or translation");
  }
  tracker_options.subspace = *subspace;
  if (!options.measurement_sigma.empty()) {
    tracker_options.measurement_sigma =
        ParsePositive("--measurement-sigma", options.measurement_sigma, "σ in pixels");
    CheckPixelSigma("--measurement-sigma", *tracker_options.measurement_sigma);
  }
  tracker_options.search.range =
      ParsePositive("--search-range", options.search_range, "the search range in pixels");
  if (tracker_options.search.range < 2.0 || tracker_options.search.range > 200.0) {
    throw InputError("--search-range", 0, "must be 2 … 200 px, got '" + options.search_range + "'",
                     "give the largest expected motion of the contour per frame, in pixels");
  }
  if (options.init_points != "control" && options.init_points != "curve") {
    throw InputError("--init-points", 0, "unknown kind '" + options.init_points + "'",
                     "use control (B-spline control points) or curve (points on the contour)");
  }
  const OutputKind output_kind = ParseOutputKind(options.output);
  io::CheckOutputs({{"--output", options.output}}, {{"--init", options.init}});

  Eigen::Matrix2Xd control = ReadContourFile(options.init);
  if (options.init_points == "curve") {
    control = contour::ClosedBSpline::Interpolating(control).control_points();
  }
  const Eigen::Vector2d principal =
      options.principal_point.empty() ? Eigen::Vector2d(control.rowwise().mean()) : [&] {
        const std::vector<double> p =
            ParseNumberList("--principal-point", options.principal_point, 2, "CX,CY (px)");
        return Eigen::Vector2d(p[0], p[1]);
      }();
  // The pose model: the contour paper's weak perspective, or the perspective correction
  // (contour/perspective_pose.h), which needs the true principal point; auto picks it when
  // --principal-point is given.
  if (options.pose_model != "auto" && options.pose_model != "weak" &&
      options.pose_model != "perspective") {
    throw InputError("--pose-model", 0, "unknown pose model '" + options.pose_model + "'",
                     "use auto, weak or perspective");
  }
  const bool perspective = UsesPerspectivePose(options);
  const contour::SequenceTrackingOptions tracking{control, principal,   camera,
                                                  *form,   perspective, tracker_options};
  contour::SequenceTracker tracker(tracking);
  io.out << "pose model: "
         << (perspective
                 ? "perspective (weak-perspective bias removed, principal point given)"
                 : "weak perspective (the contour paper's; give --principal-point for perspective)")
         << "\n";
#if defined(HECAL_HAVE_OPENCV_PEERS)
  const std::array<std::string_view, 6> names = contour::PoseParameterNames(*form);
  // One line per frame on stdout, as it is tracked.
  const auto print = [&](const vision::TrackedImage& image) {
    const contour::SequenceFrame& frame = image.frame;
    char line[256];
    std::snprintf(line, sizeof line, "%4d %-24s %-8s edges %3d/%3d  σ %.3f px", frame.tracked.frame,
                  image.image.c_str(), std::string(contour::FrameStatusName(frame.status)).c_str(),
                  frame.tracked.edges_used, frame.tracked.edges_searched, frame.tracked.sigma);
    io.out << line;
    if (frame.pose) {
      const Vector6d& p = frame.pose->parameters;
      std::snprintf(line, sizeof line, "  T = (%.3f, %.3f, %.3f)  %s,%s,%s = (%.3f, %.3f, %.3f)°",
                    p(0), p(1), p(2), std::string(names[3]).c_str(), std::string(names[4]).c_str(),
                    std::string(names[5]).c_str(), p(3) * kDegrees, p(4) * kDegrees,
                    p(5) * kDegrees);
      io.out << line << (frame.pose->any_biased ? "  (bias)" : "");
    }
    io.out << "\n";
  };
  const std::vector<vision::TrackedImage> frames =
      vision::TrackImageSequence(options.images, &tracker, print);
  if (output_kind != OutputKind::kNone) {
    const report::ContourTrack track{tracking, tracker.tracker().template_shape(),
                                     tracker.tracker().polarity(), frames};
    io::WriteFileAtomically(options.output, output_kind == OutputKind::kCsv
                                                ? report::ContourTrackCsv(track)
                                                : report::ContourTrackJson(track));
  }
#else
  (void)output_kind;
  NeedsVision("--images");
#endif
}

// ---- render ------------------------------------------------------------------------------------

#if defined(HECAL_HAVE_OPENCV_PEERS)
namespace {

// Creates the output folder of `contour render` when it is missing; returns the topmost folder
// created (to remove on failure), nullopt when it existed. An existing path that is not a folder
// is an InputError.
std::optional<fs::path> CreateFolder(const std::string& output) {
  std::error_code error;
  const fs::file_status status = fs::status(output, error);
  if (fs::exists(status)) {
    if (!fs::is_directory(status)) {
      throw InputError(output, 0, "cannot write the frames: it exists and is not a folder",
                       "give --output a folder (created when missing)");
    }
    return std::nullopt;
  }
  fs::path topmost = fs::absolute(output, error);
  while (topmost.has_parent_path() && topmost.parent_path() != topmost &&
         !fs::exists(topmost.parent_path(), error)) {
    topmost = topmost.parent_path();
  }
  fs::create_directories(output, error);
  if (error || !fs::is_directory(output)) {
    throw InputError(output, 0, "cannot create the output folder: " + error.message(),
                     "give --output a folder that can be created or written");
  }
  return topmost;
}

std::string FrameName(int t) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%04d.png", t);
  return name;
}

// truth.csv: the motion of every frame and the weak-perspective S of it.
std::string TruthCsv(const contour::SequenceRenderOptions& options,
                     const contour::RenderedSequence& rendered) {
  std::string truth =
      "# hecal " + std::string(kVersion) +
      " contour render: x_camera = R p + (Tx, Ty, Z0 + Tz), R = Rz(Rz) Ry(Ry) Rx(Rx); Z0 = " +
      io::FormatDouble(options.camera.z0) + ", f = " + io::FormatDouble(options.camera.focal) +
      " px, principal point " + io::FormatDouble(rendered.principal.x()) + "," +
      io::FormatDouble(rendered.principal.y()) +
      "; tx..m12: the weak-perspective shape vector of the motion (tx, ty in px); noise seed " +
      std::to_string(options.seed) +
      "\n"
      "frame,image,Tx,Ty,Tz,Rx_deg,Ry_deg,Rz_deg,tx,ty,m11m1,m22m1,m21,m12\n";
  for (const contour::RenderedFrame& frame : rendered.frames) {
    truth += std::to_string(frame.index) + "," + FrameName(frame.index);
    for (int i = 0; i < 6; ++i) {
      truth += ",";
      io::AppendDouble(frame.motion(i), &truth);
    }
    for (int i = 0; i < 6; ++i) {
      truth += ",";
      io::AppendDouble(frame.shape(i), &truth);
    }
    truth += "\n";
  }
  return truth;
}

// init.csv: the control points of the first view, ready for `track --init`.
std::string InitCsv(const contour::RenderedSequence& rendered) {
  std::string init = "# hecal contour render: control points of the first view (px)\nx,y\n";
  for (Eigen::Index i = 0; i < rendered.first_view.cols(); ++i) {
    io::AppendDouble(rendered.first_view(0, i), &init);
    init += ",";
    io::AppendDouble(rendered.first_view(1, i), &init);
    init += "\n";
  }
  return init;
}

// Renders the sequence into the output folder (created before the first frame is written):
// every file is staged and renamed when all are rendered (io/atomic_file.h). `created` receives
// the topmost folder created, to remove on failure.
void RenderFrames(const ContourRenderOptions& options,
                  const contour::SequenceRenderOptions& sequence, std::optional<fs::path>* created,
                  const Io& io) {
  io::StagedFiles staged;
  bool folder_ready = false;
  const contour::RenderedSequence rendered = contour::RenderSequence(
      sequence, [&](const contour::RenderedFrame& frame, const contour::GrayImage& image) {
        if (!folder_ready) {
          *created = CreateFolder(options.output);
          folder_ready = true;
        }
        const std::string path = (fs::path(options.output) / FrameName(frame.index)).string();
        staged.Stage("--output", path, vision::EncodePng(image, path));
      });
  staged.Stage("--output", (fs::path(options.output) / "init.csv").string(), InitCsv(rendered));
  staged.Stage("--output", (fs::path(options.output) / "truth.csv").string(),
               TruthCsv(sequence, rendered));
  staged.Commit();
  io.out << "rendered " << sequence.frames << " frames (" << sequence.width << "×"
         << sequence.height << ") to " << options.output << "\n";
  if (rendered.outside > 0) {
    io.err << "hecal: warning: the target leaves the image in " << rendered.outside
           << " frame(s); the tracker cannot follow it there (fix: a smaller motion or a larger "
              "--size)\n";
  }
}
}  // namespace
#endif

void RunContourRender(const ContourRenderOptions& options, const Io& io) {
  const contour::ContourCamera camera = ParseContourCamera(options.focal, options.z0);
  const int frames = ParseCount("--frames", options.frames, 1, kMaxFrames, "the number of frames");
  const std::vector<double> from =
      ParseNumberList("--from", options.from, 6, "TX,TY,TZ,RX,RY,RZ (Z0's unit, degrees)");
  const std::vector<double> to =
      ParseNumberList("--to", options.to, 6, "TX,TY,TZ,RX,RY,RZ (Z0's unit, degrees)");
  const std::vector<double> size = ParseNumberList("--size", options.size, 2, "W,H (px)");
  for (double v : size) {
    if (v != std::floor(v) || v < io::kMinImageSide || v > kMaxRenderSide) {
      throw InputError("--size", 0,
                       "W and H must be whole numbers from " + std::to_string(io::kMinImageSide) +
                           " to " + std::to_string(kMaxRenderSide),
                       "give the image size in pixels, e.g. 768,576");
    }
  }
  const int width = static_cast<int>(size[0]), height = static_cast<int>(size[1]);
  const std::int64_t pixels = std::int64_t{width} * height;
  if (pixels > io::kMaxImagePixels || pixels * frames > kMaxSequencePixels) {
    throw InputError("--size", 0,
                     std::to_string(frames) + " frames of " + std::to_string(width) + "×" +
                         std::to_string(height) + " px are more than " +
                         std::to_string(io::kMaxImagePixels) + " pixels a frame or " +
                         std::to_string(kMaxSequencePixels) + " in all",
                     "give a smaller --size or fewer --frames");
  }
  contour::RenderOptions render;
  render.noise_sigma = ParseNumber("--noise", options.noise, "the noise σ in grey levels");
  if (!(render.noise_sigma >= 0.0 && render.noise_sigma <= kMaxGreyNoise)) {
    throw InputError("--noise", 0, "must be 0 … 255 grey levels",
                     "give the noise σ in grey levels (e.g. 3)");
  }
  render.blur_sigma = ParseNumber("--blur", options.blur, "the blur σ in pixels");
  if (render.blur_sigma < 0.0 || render.blur_sigma > 20.0) {
    throw InputError("--blur", 0, "must be 0 … 20 px", "give the optics blur σ (e.g. 0.7)");
  }
  contour::SequenceRenderOptions sequence;
  sequence.seed = ParseSeed("--seed", options.seed);
  render.quantize = true;
  sequence.render = render;
  sequence.target =
      options.contour.empty() ? contour::DefaultTarget() : ReadContourFile(options.contour);
  sequence.camera = camera;
  sequence.frames = frames;
  sequence.from = Eigen::Map<const Vector6d>(from.data());
  sequence.to = Eigen::Map<const Vector6d>(to.data());
  sequence.width = width;
  sequence.height = height;
#if !defined(HECAL_HAVE_OPENCV_PEERS)
  (void)io;
  (void)sequence;
  NeedsVision("--output");
#else
  // A folder created here is removed again when the command fails.
  std::optional<fs::path> created;
  try {
    RenderFrames(options, sequence, &created, io);
  } catch (...) {
    if (created) {
      std::error_code ignored;
      fs::remove_all(*created, ignored);
    }
    throw;
  }
#endif
}

// ---- registration ------------------------------------------------------------------------------

void AddContourTrackCommand(CLI::App& contour, const Io& io) {
  auto options = std::make_shared<ContourTrackOptions>();
  CLI::App* track = contour.add_subcommand(
      "track", "Track a planar contour through images (shape-space Kalman filter) → motion");
  track->add_option("--images", options->images, "Folder of the image sequence (sorted by name)")
      ->required();
  track->add_option("--init", options->init, "Initial contour in the first image: CSV x,y (px)")
      ->required();
  track->add_option("--focal", options->focal, "Focal length F (px)")->required();
  track->add_option("--z0", options->z0, "Initial distance Z0 (the unit of the translation)")
      ->required();
  track->add_option("--pose-model", options->pose_model,
                    "auto (default: perspective with --principal-point, else weak), weak (the "
                    "contour paper's weak perspective) or perspective (its bias removed)");
  track->add_option("--principal-point", options->principal_point,
                    "CX,CY (px; default: centroid of the init control points)");
  track->add_option("--init-points", options->init_points,
                    "control (default: B-spline control points) or curve (points on it)");
  track->add_option("--subspace", options->subspace,
                    "full (default), similarity, translation-scale, planar-robot, translation");
  track->add_option("--rotation", options->rotation, "zyx (default; roll–pitch–yaw) or zxz");
  track->add_option("--measurement-sigma", options->measurement_sigma,
                    "Edge-location σ (px; default: estimated per frame)");
  track->add_option("--search-range", options->search_range,
                    "± px searched along each normal (default 10)");
  track->add_option("--output", options->output,
                    "track.csv (a row per frame) or track.json (full covariances), atomic");
  track->callback([options, io] { RunContourTrack(*options, io); });
}

void AddContourRenderCommand(CLI::App& contour, const Io& io) {
  auto options = std::make_shared<ContourRenderOptions>();
  CLI::App* render = contour.add_subcommand(
      "render", "Render a synthetic sequence of a moving planar contour target (known motion)");
  render->add_option("--output", options->output, "Output folder (created when missing)")
      ->required();
  render->add_option("--contour", options->contour,
                     "Target control points: CSV x,y in its plane (Z0's unit; default built-in)");
  render->add_option("--frames", options->frames, "Number of frames (default 30)");
  render->add_option("--from", options->from,
                     "TX,TY,TZ,RX,RY,RZ of the first frame (Z0's unit, degrees; default 0)");
  render->add_option("--to", options->to, "TX,TY,TZ,RX,RY,RZ of the last frame")->required();
  render->add_option("--focal", options->focal, "Focal length F (px)")->required();
  render->add_option("--z0", options->z0, "Initial distance Z0")->required();
  render->add_option("--size", options->size, "W,H (px)")->required();
  render->add_option("--noise", options->noise, "Pixel noise σ (grey levels; default 3)");
  render->add_option("--blur", options->blur, "Optics blur σ (px; default 0.7)");
  render->add_option("--seed", options->seed, "Noise seed (default 1)");
  render->callback([options, io] { RunContourRender(*options, io); });
}

}  // namespace hecal::cli
