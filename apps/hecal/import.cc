// `hecal import`: see import.h and docs/import-formats.md.
#include "import.h"

#include <CLI/CLI.hpp>
#include <memory>
#include <optional>

#include "hecal/core/error.h"
#include "hecal/io/atomic_file.h"
#include "hecal/io/import.h"
#include "hecal/io/import_output.h"
#include "hecal/io/pose_table.h"
#include "hecal/io/units.h"
#include "hecal/version.h"

namespace hecal::cli {
namespace {

constexpr const char* kImportFooter =
    R"(Formats and INPUTs (conventions: docs/import-formats.md):
  moveit        pose_samples.json                 [M_eef, M_obj] pairs, m
  easy_handeye  NAME.samples (YAML)               robot inverted for eye_on_base, m
                (--setup eye-in-hand|eye-to-hand when the file does not say)
  camodocal     TransformPairsInput.yml           T1_i = T_base_ee, T2_i = T_camera_marker, m
  ethz          ROBOT.csv CAMERA.csv              camera stream (T_W_E) inverted; stamps kept;
                                                  streams unsynchronised (not paired), m
  tabb          robot_cali.txt cali.txt | DIR     robot (B_i = T_gripper_base) inverted, mm
                (--intrinsics camera.yaml writes fx, fy, cx, cy and distortion from cali.txt)
  opencv-yaml   FILE.yml                          R_/t_gripper2base, R_/t_target2cam (or T_...)
                                                  lists; --units m|mm (default m)
  matrix16      ROBOT.txt [CAMERA.txt]            16 numbers per line (row-major 4x4), read as
                                                  T_base_gripper / T_camera_target; --units m|mm
  visp          DIR | FILE... | 'GLOB'...         ViSP vpPoseVector YAML per station, paired by <i>:
                                                  [prefix]pose_rPe_<i>.yaml (or pose_fPe_) = rMe,
                                                  [prefix]pose_cPo_<i>.yaml = cMo, used as is, m
Any format: --robot-inverse / --camera-inverse when the file holds the inverse of what the format
  documents (every pose of that side is inverted after the format's convention).
Output: robot.csv = T_base_gripper, camera.csv = T_camera_target, quaternions qw,qx,qy,qz, an id
  column, a stamp column when the source has stamps, lengths in the source's unit (x_mm for mm),
  '#' lines naming the source, the convention applied and the units, and '# note:' lines for
  rotations that were projected onto SO(3) or normalised (also printed as warnings).
Errors: one line on stderr, exit code 2, and no output file is written or changed.)";

}  // namespace

void RunImport(const ImportCommandOptions& options, const Io& io) {
  const std::optional<io::ImportFormat> format = io::ParseImportFormat(options.format);
  if (!format) {
    throw InputError("--format", 0, "unknown import format '" + options.format + "'",
                     "use one of " + io::ImportFormatList());
  }
  io::ImportOptions import_options;
  if (!options.units.empty()) {
    import_options.units = io::ParseLengthUnit(options.units);
    if (!import_options.units) {
      throw InputError("--units", 0, "unknown length unit '" + options.units + "'", "use m or mm");
    }
  }
  if (!options.setup.empty()) {
    if (options.setup == "eye-in-hand") {
      import_options.setup = io::ImportSetup::kEyeInHand;
    } else if (options.setup == "eye-to-hand") {
      import_options.setup = io::ImportSetup::kEyeToHand;
    } else {
      throw InputError("--setup", 0, "unknown setup '" + options.setup + "'",
                       "use eye-in-hand or eye-to-hand");
    }
  }
  import_options.robot_inverse = options.robot_inverse;
  import_options.camera_inverse = options.camera_inverse;
  const bool robot_only = *format == io::ImportFormat::kMatrix16 && options.inputs.size() == 1;
  if (options.camera.empty() && !robot_only) {
    throw InputError("--camera", 0, "is required for --format " + options.format,
                     "give --camera camera.csv (only a robot-only matrix16 import may omit it)");
  }
  if (!options.camera.empty() && robot_only) {
    throw InputError("--camera", 0, "given, but matrix16 got only a robot file",
                     "pass the camera matrix file after the robot file, or drop --camera");
  }
  if (!options.intrinsics.empty() && *format != io::ImportFormat::kTabb) {
    throw InputError("--intrinsics", 0,
                     "only tabb sources hold intrinsics (cali.txt), not " + options.format,
                     "drop --intrinsics");
  }

  const io::ImportedPoses imported = io::ImportFiles(*format, options.inputs, import_options);

  const io::ImportTexts texts = io::FormatImportedPoses(
      imported, "written by hecal " + std::string(kVersion) + " import --format " + options.format);
  std::vector<io::OutputFile> outputs;
  outputs.push_back({"--robot", options.robot, texts.robot});
  if (texts.camera) outputs.push_back({"--camera", options.camera, *texts.camera});
  if (!options.intrinsics.empty()) {
    if (!texts.intrinsics) {
      throw InputError(options.inputs.back(), 0,
                       "the images do not share one camera model (intrinsics differ between "
                       "lines), so no single camera.yaml can be written",
                       "drop --intrinsics");
    }
    outputs.push_back({"--intrinsics", options.intrinsics, *texts.intrinsics});
  }
  std::vector<io::PathArgument> output_paths, inputs;
  for (const io::OutputFile& output : outputs) output_paths.push_back({output.flag, output.path});
  for (const std::string& source : imported.sources) inputs.push_back({"input", source});
  io::CheckOutputs(output_paths, inputs);
  io::WriteFilesAtomically(outputs);
  for (const std::string& warning : imported.robot.warnings) {
    io.err << "hecal: warning: " << warning << "\n";
  }
  if (imported.camera) {
    for (const std::string& warning : imported.camera->warnings) {
      io.err << "hecal: warning: " << warning << "\n";
    }
  }

  const std::string unit(io::UnitName(imported.robot.unit));
  io.out << "hecal: wrote " << imported.robot.rows.size() << " robot poses (T_base_gripper, "
         << unit << ") to " << options.robot;
  if (imported.camera) {
    io.out << " and " << imported.camera->rows.size() << " camera poses (T_camera_target, "
           << io::UnitName(imported.camera->unit) << ") to " << options.camera;
  }
  if (!options.intrinsics.empty()) io.out << ", intrinsics to " << options.intrinsics;
  io.out << "\n";
  if (!imported.synchronised) {
    io.out << "hecal: note: the robot and camera streams are unsynchronised; their rows are not "
              "stations (associate them by stamp before calibrating)\n";
  }
}

void RegisterImportCommand(CLI::App& app, const Io& io) {
  CLI::App* command = app.add_subcommand(
      "import", "Convert another tool's calibration samples into robot.csv and camera.csv");
  auto options = std::make_shared<ImportCommandOptions>();
  command->add_option("--format", options->format, io::ImportFormatList())->required();
  command->add_option("inputs", options->inputs, "INPUT... (see below)")->required();
  command->add_option("--robot", options->robot, "output: robot poses T_base_gripper (CSV)")
      ->required();
  command->add_option("--camera", options->camera, "output: camera poses T_camera_target (CSV)");
  command->add_option("--units", options->units,
                      "m|mm: length unit of matrix16 and opencv-yaml inputs (default m)");
  command->add_option("--setup", options->setup,
                      "eye-in-hand|eye-to-hand: for easy_handeye files that do not say");
  command->add_flag("--robot-inverse", options->robot_inverse,
                    "the robot file holds the inverse of the format's convention; invert it");
  command->add_flag("--camera-inverse", options->camera_inverse,
                    "the camera file holds the inverse of the format's convention; invert it");
  command->add_option("--intrinsics", options->intrinsics,
                      "tabb: also write the camera intrinsics of cali.txt (camera.yaml)");
  command->footer(kImportFooter);
  command->callback([options, io] { RunImport(*options, io); });
}

}  // namespace hecal::cli
