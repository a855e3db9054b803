// `hecal contour track` and `hecal contour render` (docs/cli.md#hecal-contour-track,
// docs/cli.md#hecal-contour-render, docs/contour.md): the flags bound into the options of
// jobs/contour_tracking.h and jobs/contour_rendering.h, which validate themselves (field_flags.h
// names the flag); these commands print the frames as they come and write the files:
// report/contour_track_file.h's CSV or JSON (by --output's extension), and the rendered folder
// all or none (io/atomic_file.h, StagedFolder). Without the vision layer both refuse to run.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "bounds.h"
#include "choice_flags.h"
#include "contour.h"
#include "hecal/hecal.h"
// The jobs' options are plain structs, bound in every build; the jobs run with the vision layer.
#include "job_output.h"

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
  const std::string extension = io::Lowercase(fs::path(output).extension().string());
  if (extension == ".csv") return OutputKind::kCsv;
  if (extension == ".json") return OutputKind::kJson;
  throw InputError("--output", 0, "unknown output format '" + output + "'",
                   "name the file *.csv (one row per frame) or *.json (full covariances)");
}

struct TrackCommand {
  jobs::ContourTrackingOptions options;
  std::string output;
};

void RunTrack(const TrackCommand& command, const Io& io) {
  const OutputKind output_kind = ParseOutputKind(command.output);
  io::CheckOutputs({{"--output", command.output}}, {{"--init", command.options.init}});
#if defined(HECAL_HAVE_OPENCV_PEERS)
  // One line per frame on stdout, as it is tracked.
  const contour::RotationForm form = command.options.tracking.form;
  const report::ContourTrack track = jobs::TrackContourImages(
      command.options, PrintingCallbacks(io),
      [&](const contour::TrackedImage& image) { io.out << report::ContourTrackLine(image, form); });
  if (output_kind != OutputKind::kNone) {
    io::WriteFileAtomically(command.output, output_kind == OutputKind::kCsv
                                                ? report::ContourTrackCsv(track)
                                                : report::ContourTrackJson(track));
  }
#else
  (void)output_kind;
  (void)io;
  NeedsVision("--images");
#endif
}

// ---- render ------------------------------------------------------------------------------------

struct RenderCommand {
  jobs::ContourRenderingOptions options;
  std::string output;
};

void RunRender(const RenderCommand& command, const Io& io) {
#if !defined(HECAL_HAVE_OPENCV_PEERS)
  (void)command;
  (void)io;
  NeedsVision("--output");
#else
  // The folder is created at the first frame, and removed again when the command fails.
  io::StagedFolder folder("--output", command.output, "the frames");
  const jobs::ContourRendering rendered = jobs::RenderContourSequence(
      command.options,
      [&folder](const std::string& name, const std::string& png) { folder.Stage(name, png); });
  folder.Stage("init.csv", rendered.init_csv);
  folder.Stage("truth.csv", rendered.truth_csv);
  folder.Commit();
  const contour::SequenceRenderOptions& sequence = rendered.options;
  io.out << "rendered " << sequence.frames << " frames (" << sequence.width << "×"
         << sequence.height << ") to " << command.output << "\n";
  if (rendered.rendered.outside > 0) {
    io.err << "hecal: warning: the target leaves the image in " << rendered.rendered.outside
           << " frame(s); the tracker cannot follow it there (fix: a smaller motion or a larger "
              "--size)\n";
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
  jobs::ContourTrackingOptions& track_options = command->options;
  contour::SequenceTrackingOptions& o = track_options.tracking;
  CLI::App* track = contour.add_subcommand(
      "track", "Track a planar contour through images (shape-space Kalman filter) → motion");
  track
      ->add_option("--images", track_options.images,
                   "Folder of the image sequence (sorted by name)")
      ->required();
  track
      ->add_option("--init", track_options.init, "Initial contour in the first image: CSV x,y (px)")
      ->required();
  track->add_option("--focal", o.camera.focal, "Focal length F (px)")->required();
  track->add_option("--z0", o.camera.z0, "Initial distance Z0 (the unit of the translation)")
      ->required();
  AddChoice<std::optional<bool>>(
      *track, "--pose-model", track_options.perspective,
      [](std::string_view text) -> std::optional<std::optional<bool>> {
        std::optional<std::optional<bool>> model;  // nullopt: no pose model of that name
        if (text == "auto") model.emplace(std::nullopt);
        if (text == "weak" || text == "perspective") model.emplace(text != "weak");
        return model;
      },
      "pose model", "auto, weak or perspective",
      "auto (default: perspective with --principal-point, else weak), weak (the "
      "contour paper's weak perspective) or perspective (its bias removed)");
  track->add_option_function<std::string>(
      "--principal-point",
      [&track_options](const std::string& text) {
        const std::vector<double> p = ParseNumberList("--principal-point", text, 2, "CX,CY (px)");
        track_options.principal = Eigen::Vector2d(p[0], p[1]);
      },
      "CX,CY (px; default: centroid of the init control points)");
  AddChoice<bool>(
      *track, "--init-points", track_options.init_on_curve,
      [](std::string_view text) -> std::optional<bool> {
        if (text == "control" || text == "curve") return text == "curve";
        return std::nullopt;
      },
      "kind", "control (B-spline control points) or curve (points on the contour)",
      "control (default: B-spline control points) or curve (points on it)");
  AddChoice<contour::ShapeSubspace>(
      *track, "--subspace", o.tracker.subspace, contour::ParseShapeSubspace, "shape subspace",
      "full, similarity, translation-scale, planar-robot or translation",
      "full (default), similarity, translation-scale, planar-robot, translation");
  AddRotationFlag(*track, o.form);
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
  contour::SequenceRenderOptions& o = command->options.sequence;
  o.render.noise_sigma = 3.0;
  o.render.quantize = true;
  CLI::App* render = contour.add_subcommand(
      "render", "Render a synthetic sequence of a moving planar contour target (known motion)");
  render->add_option("--output", command->output, "Output folder (created when missing)")
      ->required();
  render->add_option("--contour", command->options.contour,
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
