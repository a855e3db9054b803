// `hecal contour track` and `hecal contour render` (docs/cli.md#hecal-contour-track,
// docs/cli.md#hecal-contour-render, docs/contour.md): the jobs contour::SequenceTracker and
// contour::RenderSequence (contour/sequence.h) over options that validate themselves, with the
// images read and encoded by vision/contour_images.h and the text files written by
// report/contour_track_file.h and report/contour_render_file.h; these commands bind the flags,
// print and write the files.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bounds.h"
#include "contour.h"
#include "hecal/contour/bspline.h"
#include "hecal/contour/contour_study.h"
#include "hecal/contour/sequence.h"
#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/io/atomic_file.h"
#include "hecal/report/contour_render_file.h"
#include "hecal/report/contour_track_file.h"
#include "hecal/report/contour_track_text.h"
#if defined(HECAL_HAVE_OPENCV_PEERS)
#include "hecal/vision/contour_images.h"
#endif

namespace hecal::cli {
namespace {

namespace fs = std::filesystem;

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
  std::string extension = fs::path(output).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension == ".csv") return OutputKind::kCsv;
  if (extension == ".json") return OutputKind::kJson;
  throw InputError("--output", 0, "unknown output format '" + output + "'",
                   "name the file *.csv (one row per frame) or *.json (full covariances)");
}

struct TrackCommand {
  contour::SequenceTrackingOptions options;  // control and principal point: from the files
  std::string images, init, output;
  bool curve = false;                        // --init-points curve
  std::optional<Eigen::Vector2d> principal;  // --principal-point
  std::optional<bool> perspective;           // --pose-model; auto: with --principal-point
};

void RunTrack(TrackCommand command, const Io& io) {
  contour::SequenceTrackingOptions& tracking = command.options;
  // The pose model: the contour paper's weak perspective, or the perspective correction
  // (contour/perspective_pose.h), which needs the true principal point; auto picks it when
  // --principal-point is given.
  tracking.perspective = command.perspective.value_or(command.principal.has_value());
  RequireValid(tracking);
  const OutputKind output_kind = ParseOutputKind(command.output);
  io::CheckOutputs({{"--output", command.output}}, {{"--init", command.init}});

  tracking.control = ReadContourFile(command.init);
  if (command.curve) {
    tracking.control = contour::ClosedBSpline::Interpolating(tracking.control).control_points();
  }
  tracking.principal = command.principal.value_or(tracking.control.rowwise().mean());
  contour::SequenceTracker tracker(tracking);
  io.out << "pose model: "
         << (tracking.perspective
                 ? "perspective (weak-perspective bias removed, principal point given)"
                 : "weak perspective (the contour paper's; give --principal-point for perspective)")
         << "\n";
#if defined(HECAL_HAVE_OPENCV_PEERS)
  // One line per frame on stdout, as it is tracked.
  const auto print = [&](const vision::TrackedImage& image) {
    io.out << report::ContourTrackLine(image, tracking.form);
  };
  const std::vector<vision::TrackedImage> frames =
      vision::TrackImageSequence(command.images, &tracker, print);
  if (output_kind != OutputKind::kNone) {
    const report::ContourTrack track{tracking, tracker.tracker().template_shape(),
                                     tracker.tracker().polarity(), frames};
    io::WriteFileAtomically(command.output, output_kind == OutputKind::kCsv
                                                ? report::ContourTrackCsv(track)
                                                : report::ContourTrackJson(track));
  }
#else
  (void)output_kind;
  NeedsVision("--images");
#endif
}

// ---- render ------------------------------------------------------------------------------------

struct RenderCommand {
  contour::SequenceRenderOptions options;
  std::string output, contour;  // --contour: the target's control points, read into options
};

#if defined(HECAL_HAVE_OPENCV_PEERS)
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

// Renders the sequence into the output folder (created before the first frame is written):
// every file is staged and renamed when all are rendered (io/atomic_file.h). `created` receives
// the topmost folder created, to remove on failure.
void RenderFrames(const RenderCommand& command, std::optional<fs::path>* created, const Io& io) {
  const contour::SequenceRenderOptions& sequence = command.options;
  const fs::path folder(command.output);
  io::StagedFiles staged;
  bool folder_ready = false;
  const contour::RenderedSequence rendered = contour::RenderSequence(
      sequence, [&](const contour::RenderedFrame& frame, const contour::GrayImage& image) {
        if (!folder_ready) {
          *created = CreateFolder(command.output);
          folder_ready = true;
        }
        const std::string path = (folder / report::RenderedFrameName(frame.index)).string();
        staged.Stage("--output", path, vision::EncodePng(image, path));
      });
  staged.Stage("--output", (folder / "init.csv").string(), report::RenderInitCsv(rendered));
  staged.Stage("--output", (folder / "truth.csv").string(),
               report::RenderTruthCsv(sequence, rendered));
  staged.Commit();
  io.out << "rendered " << sequence.frames << " frames (" << sequence.width << "×"
         << sequence.height << ") to " << command.output << "\n";
  if (rendered.outside > 0) {
    io.err << "hecal: warning: the target leaves the image in " << rendered.outside
           << " frame(s); the tracker cannot follow it there (fix: a smaller motion or a larger "
              "--size)\n";
  }
}
#endif

void RunRender(RenderCommand command, const Io& io) {
  contour::SequenceRenderOptions& sequence = command.options;
  sequence.target =
      command.contour.empty() ? contour::DefaultTarget() : ReadContourFile(command.contour);
  RequireValid(sequence);
#if !defined(HECAL_HAVE_OPENCV_PEERS)
  (void)io;
  NeedsVision("--output");
#else
  // A folder created here is removed again when the command fails.
  std::optional<fs::path> created;
  try {
    RenderFrames(command, &created, io);
  } catch (...) {
    if (created) {
      std::error_code ignored;
      fs::remove_all(*created, ignored);
    }
    throw;
  }
#endif
}

// A motion TX,TY,TZ,RX,RY,RZ (Z0's unit, degrees).
Vector6d ParseMotion(const std::string& flag, const std::string& text) {
  const std::vector<double> motion =
      ParseNumberList(flag, text, 6, "TX,TY,TZ,RX,RY,RZ (Z0's unit, degrees)");
  return Eigen::Map<const Vector6d>(motion.data());
}

}  // namespace

// ---- registration ------------------------------------------------------------------------------

void AddContourTrackCommand(CLI::App& contour, const Io& io) {
  auto command = std::make_shared<TrackCommand>();
  contour::SequenceTrackingOptions& o = command->options;
  CLI::App* track = contour.add_subcommand(
      "track", "Track a planar contour through images (shape-space Kalman filter) → motion");
  track->add_option("--images", command->images, "Folder of the image sequence (sorted by name)")
      ->required();
  track->add_option("--init", command->init, "Initial contour in the first image: CSV x,y (px)")
      ->required();
  track->add_option("--focal", o.camera.focal, "Focal length F (px)")->required();
  track->add_option("--z0", o.camera.z0, "Initial distance Z0 (the unit of the translation)")
      ->required();
  track->add_option_function<std::string>(
      "--pose-model",
      [command](const std::string& text) {
        if (text == "auto") {
          command->perspective.reset();
        } else if (text == "weak" || text == "perspective") {
          command->perspective = text == "perspective";
        } else {
          throw InputError("--pose-model", 0, "unknown pose model '" + text + "'",
                           "use auto, weak or perspective");
        }
      },
      "auto (default: perspective with --principal-point, else weak), weak (the "
      "contour paper's weak perspective) or perspective (its bias removed)");
  track->add_option_function<std::string>(
      "--principal-point",
      [command](const std::string& text) {
        const std::vector<double> p = ParseNumberList("--principal-point", text, 2, "CX,CY (px)");
        command->principal = Eigen::Vector2d(p[0], p[1]);
      },
      "CX,CY (px; default: centroid of the init control points)");
  track->add_option_function<std::string>(
      "--init-points",
      [command](const std::string& text) {
        if (text != "control" && text != "curve") {
          throw InputError(
              "--init-points", 0, "unknown kind '" + text + "'",
              "use control (B-spline control points) or curve (points on the contour)");
        }
        command->curve = text == "curve";
      },
      "control (default: B-spline control points) or curve (points on it)");
  track->add_option_function<std::string>(
      "--subspace",
      [&o](const std::string& text) {
        const std::optional<contour::ShapeSubspace> subspace = contour::ParseShapeSubspace(text);
        if (!subspace) {
          throw InputError("--subspace", 0, "unknown shape subspace '" + text + "'",
                           "use full, similarity, translation-scale, planar-robot or translation");
        }
        o.tracker.subspace = *subspace;
      },
      "full (default), similarity, translation-scale, planar-robot, translation");
  track->add_option_function<std::string>(
      "--rotation", [&o](const std::string& text) { o.form = ParseRotationFlag(text); },
      "zyx (default; roll–pitch–yaw) or zxz");
  track->add_option_function<double>(
      "--measurement-sigma", [&o](double sigma) { o.tracker.measurement_sigma = sigma; },
      "Edge-location σ (px; default: estimated per frame)");
  track->add_option("--search-range", o.tracker.search.range,
                    "± px searched along each normal (default 10)");
  track->add_option("--output", command->output,
                    "track.csv (a row per frame) or track.json (full covariances), atomic");
  track->callback([command, io] { RunTrack(*command, io); });
}

void AddContourRenderCommand(CLI::App& contour, const Io& io) {
  auto command = std::make_shared<RenderCommand>();
  contour::SequenceRenderOptions& o = command->options;
  o.render.noise_sigma = 3.0;
  o.render.quantize = true;
  CLI::App* render = contour.add_subcommand(
      "render", "Render a synthetic sequence of a moving planar contour target (known motion)");
  render->add_option("--output", command->output, "Output folder (created when missing)")
      ->required();
  render->add_option("--contour", command->contour,
                     "Target control points: CSV x,y in its plane (Z0's unit; default built-in)");
  AddWholeNumber(*render, "--frames", o.frames, "Number of frames (default 30)");
  render->add_option_function<std::string>(
      "--from", [&o](const std::string& text) { o.from = ParseMotion("--from", text); },
      "TX,TY,TZ,RX,RY,RZ of the first frame (Z0's unit, degrees; default 0)");
  render
      ->add_option_function<std::string>(
          "--to", [&o](const std::string& text) { o.to = ParseMotion("--to", text); },
          "TX,TY,TZ,RX,RY,RZ of the last frame")
      ->required();
  render->add_option("--focal", o.camera.focal, "Focal length F (px)")->required();
  render->add_option("--z0", o.camera.z0, "Initial distance Z0")->required();
  render
      ->add_option_function<std::string>(
          "--size",
          [&o](const std::string& text) {
            const std::vector<double> size = ParseNumberList("--size", text, 2, "W,H (px)");
            for (const double side : size) {
              if (side != std::floor(side)) {
                throw InputError("--size", 0, "W and H must be whole numbers, got '" + text + "'",
                                 "give the image size in pixels, e.g. 768,576");
              }
            }
            // Out of range sides are clamped to one past the range, for IsValid to refuse.
            const auto side = [](double v) {
              return static_cast<int>(
                  std::clamp(v, -1.0, contour::SequenceRenderOptions::kMaxSide + 1.0));
            };
            o.width = side(size[0]);
            o.height = side(size[1]);
          },
          "W,H (px)")
      ->required();
  render->add_option("--noise", o.render.noise_sigma, "Pixel noise σ (grey levels; default 3)");
  render->add_option("--blur", o.render.blur_sigma, "Optics blur σ (px; default 0.7)");
  AddWholeNumber(*render, "--seed", o.seed, "Noise seed (default 1)");
  render->callback([command, io] { RunRender(*command, io); });
}

}  // namespace hecal::cli
