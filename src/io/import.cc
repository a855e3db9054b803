#include "hecal/io/import.h"

#include <filesystem>
#include <system_error>

#include "hecal/core/options_check.h"
#include "hecal/io/atomic_file.h"
#include "hecal/io/import_camodocal.h"
#include "hecal/io/import_easy_handeye.h"
#include "hecal/io/import_ethz.h"
#include "hecal/io/import_matrix16.h"
#include "hecal/io/import_moveit.h"
#include "hecal/io/import_opencv_yaml.h"
#include "hecal/io/import_tabb.h"
#include "hecal/io/import_visp.h"
#include "import_internal.h"

namespace hecal::io {
namespace {

using import_internal::Fail;

struct FormatName {
  ImportFormat format;
  std::string_view name;
};

constexpr FormatName kFormats[] = {
    {ImportFormat::kMoveit, "moveit"},       {ImportFormat::kEasyHandeye, "easy_handeye"},
    {ImportFormat::kCamodocal, "camodocal"}, {ImportFormat::kEthz, "ethz"},
    {ImportFormat::kTabb, "tabb"},           {ImportFormat::kOpenCvYaml, "opencv-yaml"},
    {ImportFormat::kMatrix16, "matrix16"},   {ImportFormat::kVisp, "visp"},
};

std::string_view InputsUsage(ImportFormat format) {
  switch (format) {
    case ImportFormat::kMoveit:
      return "one pose_samples.json";
    case ImportFormat::kEasyHandeye:
      return "one samples YAML file";
    case ImportFormat::kCamodocal:
      return "one TransformPairsInput.yml";
    case ImportFormat::kEthz:
      return "two CSV files: the robot stream (poses_B_H), then the camera stream (poses_W_E)";
    case ImportFormat::kTabb:
      return "robot_cali.txt then cali.txt, or one directory holding both";
    case ImportFormat::kOpenCvYaml:
      return "one FileStorage YAML file";
    case ImportFormat::kMatrix16:
      return "the robot matrix file, optionally followed by the camera matrix file";
    case ImportFormat::kVisp:
      return "directories, pose_rPe_<i>.yaml / pose_cPo_<i>.yaml files or glob patterns";
  }
  return "";
}

[[noreturn]] void WrongInputCount(ImportFormat format, size_t count) {
  Fail("INPUT", 0,
       std::string(ImportFormatName(format)) + " takes " + std::string(InputsUsage(format)) +
           ", got " + std::to_string(count) + " input" + (count == 1 ? "" : "s"),
       "see docs/import-formats.md");
}

bool IsDirectory(const std::string& path) {
  std::error_code error;
  return std::filesystem::is_directory(path, error);
}

std::string JoinPath(const std::string& directory, const char* name) {
  return (std::filesystem::path(directory) / name).string();
}

// --robot-inverse / --camera-inverse: every pose of that side inverted, after the format's own
// convention, with a header line saying so.
void InvertSide(const std::string& flag, const std::string& frame, PoseTable* table,
                std::vector<std::string>* notes) {
  for (PoseRow& row : table->rows) row.pose = row.pose.inverse();
  notes->push_back("convention: " + flag +
                   ": the file holds the inverse of the convention above, so every pose was "
                   "then INVERTED to " +
                   frame);
}

// ReadFile, remembering the path in `sources`.
std::string ReadSource(std::vector<std::string>* sources, const std::string& path) {
  sources->push_back(path);
  return ReadFile(path);
}

ImportedPoses Read(ImportFormat format, const std::vector<std::string>& inputs,
                   const ImportOptions& options, std::vector<std::string>* sources) {
  const size_t count = inputs.size();
  switch (format) {
    case ImportFormat::kMoveit:
      if (count != 1) WrongInputCount(format, count);
      return ParseMoveitSamples(ReadSource(sources, inputs[0]), inputs[0]);
    case ImportFormat::kEasyHandeye:
      if (count != 1) WrongInputCount(format, count);
      return ParseEasyHandeyeSamples(ReadSource(sources, inputs[0]), inputs[0], options.setup);
    case ImportFormat::kCamodocal:
      if (count != 1) WrongInputCount(format, count);
      return ParseCamodocalPairs(ReadSource(sources, inputs[0]), inputs[0]);
    case ImportFormat::kOpenCvYaml:
      if (count != 1) WrongInputCount(format, count);
      return ParseOpenCvHandEyeYaml(ReadSource(sources, inputs[0]), inputs[0],
                                    options.units.value_or(LengthUnit::kMetre));
    case ImportFormat::kEthz: {
      if (count != 2) WrongInputCount(format, count);
      const std::string robot = ReadSource(sources, inputs[0]);
      const std::string camera = ReadSource(sources, inputs[1]);
      return ParseEthzStreams(robot, inputs[0], camera, inputs[1]);
    }
    case ImportFormat::kTabb: {
      std::string robot_path;
      std::string camera_path;
      if (count == 1 && IsDirectory(inputs[0])) {
        robot_path = JoinPath(inputs[0], "robot_cali.txt");
        camera_path = JoinPath(inputs[0], "cali.txt");
      } else if (count == 2) {
        robot_path = inputs[0];
        camera_path = inputs[1];
      } else {
        WrongInputCount(format, count);
      }
      const std::string robot = ReadSource(sources, robot_path);
      const std::string camera = ReadSource(sources, camera_path);
      return ParseTabb(robot, robot_path, camera, camera_path);
    }
    case ImportFormat::kMatrix16: {
      if (count != 1 && count != 2) WrongInputCount(format, count);
      if (count == 1 && options.camera_inverse) {
        Fail("ImportOptions.camera_inverse", 0, "given without a camera matrix file",
             "pass the camera file after the robot file, or leave camera_inverse unset");
      }
      Matrix16Options matrix_options;
      matrix_options.unit = options.units.value_or(LengthUnit::kMetre);
      const std::string robot = ReadSource(sources, inputs[0]);
      if (count == 1) return ParseMatrix16(robot, inputs[0], std::nullopt, "", matrix_options);
      const std::string camera = ReadSource(sources, inputs[1]);
      return ParseMatrix16(robot, inputs[0], std::string_view(camera), inputs[1], matrix_options);
    }
    case ImportFormat::kVisp: {
      if (count == 0) WrongInputCount(format, count);
      std::vector<VispPoseFile> files;
      for (const std::string& path : ListVispPoseFiles(inputs)) {
        files.push_back({path, ReadSource(sources, path)});
      }
      return ParseVispPoseFiles(files);
    }
  }
  Fail("ImportOptions.format", 0, "unknown import format", "use one of " + ImportFormatList());
}

}  // namespace

std::optional<ImportFormat> ParseImportFormat(std::string_view text) {
  for (const FormatName& entry : kFormats) {
    if (entry.name == text) return entry.format;
  }
  return std::nullopt;
}

std::string_view ImportFormatName(ImportFormat format) {
  for (const FormatName& entry : kFormats) {
    if (entry.format == format) return entry.name;
  }
  return "";
}

std::string ImportFormatList() {
  std::string list;
  for (const FormatName& entry : kFormats) {
    if (!list.empty()) list += '|';
    list += entry.name;
  }
  return list;
}

bool ImportOptions::IsValid(ImportFormat format, std::string* why) const {
  const std::string name(ImportFormatName(format));
  if (units && format != ImportFormat::kMatrix16 && format != ImportFormat::kOpenCvYaml) {
    return Invalid(
        why, "ImportOptions.units",
        name + " files fix their own length unit (" + (format == ImportFormat::kTabb ? "mm" : "m") +
            "), so a length unit does not apply",
        "leave the unit unset (it is for matrix16 and opencv-yaml, whose files do not say)");
  }
  if (setup && format != ImportFormat::kEasyHandeye) {
    return Invalid(why, "ImportOptions.setup",
                   "does not apply to " + name + " (only easy_handeye needs it)",
                   "leave the setup unset");
  }
  return true;
}

ImportedPoses ImportFiles(ImportFormat format, const std::vector<std::string>& inputs,
                          const ImportOptions& options) {
  std::string why;
  if (!options.IsValid(format, &why)) throw OptionsError(why);
  std::vector<std::string> sources;
  ImportedPoses poses = Read(format, inputs, options, &sources);
  poses.sources = std::move(sources);
  if (options.robot_inverse) {
    InvertSide("--robot-inverse", "T_base_gripper", &poses.robot, &poses.robot_notes);
  }
  if (options.camera_inverse && poses.camera) {
    InvertSide("--camera-inverse", "T_camera_target", &*poses.camera, &poses.camera_notes);
  }
  return poses;
}

}  // namespace hecal::io
