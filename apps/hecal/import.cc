// `hecal import`: see import.h and docs/import-formats.md.
#include "import.h"

#include <CLI/CLI.hpp>
#include <memory>
#include <optional>

#include "choice_flags.h"
#include "hecal/hecal.h"

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

void RunImport(const jobs::ImportJobOptions& options, const Io& io) {
  const jobs::ImportJob job = jobs::ImportSamples(options);
  std::vector<io::OutputFile> outputs = {{"--robot", options.robot, job.texts.robot}};
  if (job.texts.camera) outputs.push_back({"--camera", options.camera, *job.texts.camera});
  if (!options.intrinsics.empty()) {
    outputs.push_back({"--intrinsics", options.intrinsics, *job.texts.intrinsics});
  }
  std::vector<io::PathArgument> output_paths, inputs;
  for (const io::OutputFile& output : outputs) output_paths.push_back({output.flag, output.path});
  for (const std::string& source : job.imported.sources) inputs.push_back({"input", source});
  io::CheckOutputs(output_paths, inputs);
  io::WriteFilesAtomically(outputs);
  for (const std::string& warning : job.warnings) io.err << "hecal: warning: " << warning << "\n";

  const io::ImportedPoses& imported = job.imported;
  io.out << "hecal: wrote " << imported.robot.rows.size() << " robot poses (T_base_gripper, "
         << io::UnitName(imported.robot.unit) << ") to " << options.robot;
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
  auto options = std::make_shared<jobs::ImportJobOptions>();
  auto setup = std::make_shared<std::optional<handeye::Setup>>();
  AddChoice<io::ImportFormat>(*command, "--format", options->format, io::ParseImportFormat,
                              "import format", "one of " + io::ImportFormatList(),
                              io::ImportFormatList())
      ->required();
  command->add_option("inputs", options->inputs, "INPUT... (see below)")->required();
  command->add_option("--robot", options->robot, "output: robot poses T_base_gripper (CSV)")
      ->required();
  command->add_option("--camera", options->camera, "output: camera poses T_camera_target (CSV)");
  AddLengthUnitFlag(*command, "--units", options->read.units,
                    "m|mm: length unit of matrix16 and opencv-yaml inputs (default m)");
  AddSetupFlag(*command, *setup, "eye-in-hand|eye-to-hand: for easy_handeye files that do not say");
  command->add_flag("--robot-inverse", options->read.robot_inverse,
                    "the robot file holds the inverse of the format's convention; invert it");
  command->add_flag("--camera-inverse", options->read.camera_inverse,
                    "the camera file holds the inverse of the format's convention; invert it");
  command->add_option("--intrinsics", options->intrinsics,
                      "tabb: also write the camera intrinsics of cali.txt (camera.yaml)");
  command->footer(kImportFooter);
  command->callback([options, setup, io] {
    if (*setup) {
      options->read.setup = **setup == handeye::Setup::kEyeInHand ? io::ImportSetup::kEyeInHand
                                                                  : io::ImportSetup::kEyeToHand;
    }
    RunImport(*options, io);
  });
}

}  // namespace hecal::cli
