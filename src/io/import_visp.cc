#include "hecal/io/import_visp.h"

#include <fnmatch.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <system_error>

#include "import_internal.h"
#include "import_yaml.h"

namespace hecal::io {
namespace {

namespace fs = std::filesystem;
using import_internal::Fail;

constexpr const char* kNames =
    "name robot poses <prefix>pose_rPe_<i>.yaml (or pose_fPe_<i>.yaml) and camera poses "
    "<prefix>pose_cPo_<i>.yaml, as ViSP's hand-eye apps do";

enum class Side { kRobot, kCamera };

// What a pose file name says: "franka_pose_rPe_12.yaml" → robot, 12, "franka_", "rPe".
struct PoseFileName {
  Side side = Side::kRobot;
  long index = 0;
  std::string prefix;
  std::string tag;  // rPe | fPe | cPo
};

std::optional<PoseFileName> ParseName(std::string_view name) {
  const auto strip = [&name](std::string_view suffix) {
    if (name.size() < suffix.size() || name.substr(name.size() - suffix.size()) != suffix) {
      return false;
    }
    name.remove_suffix(suffix.size());
    return true;
  };
  if (!strip(".yaml") && !strip(".yml")) return std::nullopt;
  const size_t underscore = name.find_last_of('_');
  if (underscore == std::string_view::npos) return std::nullopt;
  const std::string_view digits = name.substr(underscore + 1);
  if (digits.empty() || digits.size() > 9 ||
      !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    return std::nullopt;
  }
  const long index = std::stol(std::string(digits));
  name = name.substr(0, underscore);
  for (std::string_view tag : {"rPe", "fPe", "cPo"}) {
    if (strip("pose_" + std::string(tag))) {
      return PoseFileName{tag == "cPo" ? Side::kCamera : Side::kRobot, index, std::string(name),
                          std::string(tag)};
    }
  }
  return std::nullopt;
}

bool HasWildcard(std::string_view text) {
  return text.find_first_of("*?[") != std::string_view::npos;
}

std::vector<fs::path> FilesIn(const fs::path& directory, const std::string& what) {
  std::error_code error;
  std::vector<fs::path> files;
  for (fs::directory_iterator it(directory, error), end; !error && it != end; it.increment(error)) {
    std::error_code ignored;  // a dangling link is not a file; skipped like any other
    if (it->is_regular_file(ignored)) files.push_back(it->path());
  }
  if (error) {
    Fail(what, 0, "cannot list " + directory.string() + ": " + error.message(),
         "give a readable directory");
  }
  return files;
}

// The pose's file name, for messages about a station's missing partner.
std::string PartnerName(const PoseFileName& name) {
  return name.prefix + (name.side == Side::kRobot ? "pose_cPo_" : "pose_rPe_") +
         std::to_string(name.index) + ".yaml";
}

Pose ReadPoseVector(const VispPoseFile& file, int* data_line) {
  const std::string& source = file.path;
  return import_internal::GuardYaml(source, [&] {
    const YAML::Node root = import_internal::LoadYaml(file.text, source);
    if (!root.IsDefined() || !root.IsMap()) {
      Fail(source, import_internal::LineOf(root),
           "is not a vpPoseVector YAML file (a map with rows, cols and data)",
           "save the pose with vpPoseVector::saveYAML");
    }
    long size[2] = {0, 0};
    const char* keys[2] = {"rows", "cols"};
    for (int k = 0; k < 2; ++k) {
      const std::optional<YAML::Node> node = import_internal::Find(root, keys[k]);
      if (!node) {
        Fail(source, 0, std::string("has no '") + keys[k] + "'",
             "write rows: 6, cols: 1 and data (vpPoseVector::saveYAML's layout)");
      }
      size[k] = import_internal::ScalarCount(*node, source, keys[k], 1L << 20);
    }
    if (size[0] != 6 || size[1] != 1) {
      Fail(source, import_internal::LineOf(*import_internal::Find(root, "rows")),
           "rows: " + std::to_string(size[0]) + ", cols: " + std::to_string(size[1]) +
               ", but a vpPoseVector is 6x1 (tx, ty, tz, tux, tuy, tuz)",
           "save a vpPoseVector (rows: 6, cols: 1), not another array");
    }
    const std::optional<YAML::Node> data = import_internal::Find(root, "data");
    if (!data) {
      Fail(source, 0, "has no 'data'",
           "add data: with six lines '- [value]': tx, ty, tz (m), tux, tuy, tuz (rad)");
    }
    const import_internal::Matrix matrix = import_internal::ReadMatrix(*data, source, "data");
    if (matrix.rows != 6 || matrix.cols != 1) {
      Fail(source, matrix.line,
           "data has " + std::to_string(matrix.rows) + " row" + (matrix.rows == 1 ? "" : "s") +
               " of " + std::to_string(matrix.cols) + " value" + (matrix.cols == 1 ? "" : "s") +
               ", but rows: 6, cols: 1 needs 6 rows of 1",
           "write six lines '- [value]': tx, ty, tz (m), tux, tuy, tuz (rad)");
    }
    *data_line = matrix.line;
    const std::vector<double>& v = matrix.values;
    return import_internal::PoseFromRotationVector(
        Eigen::Vector3d(v[3], v[4], v[5]), Eigen::Vector3d(v[0], v[1], v[2]), 1.0,
        import_internal::Origin{source, matrix.line, "the pose vector"});
  });
}

// "8 files in DIR: franka_pose_rPe_1.yaml ... franka_pose_rPe_8.yaml".
std::string SourceNote(const std::vector<const VispPoseFile*>& files) {
  const fs::path first(files.front()->path);
  const fs::path last(files.back()->path);
  if (files.size() == 1) return "source: " + first.string();
  const bool one_directory = std::all_of(files.begin(), files.end(), [&](const VispPoseFile* file) {
    return fs::path(file->path).parent_path() == first.parent_path();
  });
  return "source: " + std::to_string(files.size()) + " files" +
         (one_directory ? " in " + (first.has_parent_path() ? first.parent_path().string() : ".") +
                              ": " + first.filename().string() + " ... " + last.filename().string()
                        : ": " + first.string() + " ... " + last.string());
}

}  // namespace

std::vector<std::string> ListVispPoseFiles(const std::vector<std::string>& inputs) {
  std::vector<std::string> files;
  std::set<std::string> seen;
  const auto add = [&](const fs::path& path) {
    std::error_code error;
    const fs::path canonical = fs::weakly_canonical(path, error);
    if (seen.insert(error ? path.lexically_normal().string() : canonical.string()).second) {
      files.push_back(path.string());
    }
  };
  const auto require_pose_name = [](const fs::path& path) {
    if (!ParseName(path.filename().string())) {
      Fail(path.string(), 0, "is not a ViSP pose file name", kNames);
    }
  };
  for (const std::string& input : inputs) {
    const fs::path path(input);
    std::error_code error;
    if (fs::is_directory(path, error)) {
      for (const fs::path& file : FilesIn(path, input)) {
        if (ParseName(file.filename().string())) add(file);
      }
      continue;
    }
    const std::string pattern = path.filename().string();
    const fs::path directory = path.has_parent_path() ? path.parent_path() : fs::path(".");
    if (HasWildcard(directory.string())) {
      Fail(input, 0, "has wildcards in its directory part",
           "use wildcards in the file name only (e.g. data/pose_*.yaml), or give the directory");
    }
    if (!HasWildcard(pattern)) {
      require_pose_name(path);
      add(path);
      continue;
    }
    if (!fs::is_directory(directory, error)) {
      Fail(input, 0, "directory " + directory.string() + " does not exist",
           "check the path of the pattern");
    }
    size_t matches = 0;
    for (const fs::path& file : FilesIn(directory, input)) {
      if (fnmatch(pattern.c_str(), file.filename().c_str(), FNM_PERIOD) != 0) continue;
      require_pose_name(file);
      add(file);
      ++matches;
    }
    if (matches == 0) {
      Fail(input, 0, "matches no file", "check the pattern (quote it so hecal expands it)");
    }
  }
  if (files.empty()) {
    Fail(inputs.empty() ? "INPUT" : inputs.front(), 0, "holds no ViSP pose files", kNames);
  }
  std::sort(files.begin(), files.end());
  return files;
}

ImportedPoses ParseVispPoseFiles(const std::vector<VispPoseFile>& files) {
  struct Station {
    const VispPoseFile* file[2] = {nullptr, nullptr};  // robot, camera
    PoseFileName name[2];
  };
  std::map<long, Station> stations;
  for (const VispPoseFile& file : files) {
    const std::optional<PoseFileName> name = ParseName(fs::path(file.path).filename().string());
    if (!name) Fail(file.path, 0, "is not a ViSP pose file name", kNames);
    Station& station = stations[name->index];
    const int side = name->side == Side::kRobot ? 0 : 1;
    if (station.file[side]) {
      Fail(file.path, 0,
           "station " + std::to_string(name->index) + " already has a " +
               (side == 0 ? "robot" : "camera") + " pose file, " + station.file[side]->path,
           std::string("keep one file per station and side") +
               (side == 0 ? " (pose_fPe_ is the name of pose_rPe_ before ViSP 3.7)" : ""));
    }
    station.file[side] = &file;
    station.name[side] = *name;
  }
  if (stations.empty()) Fail("INPUT", 0, "no ViSP pose files", kNames);
  for (const auto& [index, station] : stations) {
    for (int side = 0; side < 2; ++side) {
      if (station.file[side]) continue;
      const VispPoseFile& other = *station.file[1 - side];
      const std::string partner = PartnerName(station.name[1 - side]);
      Fail(other.path, 0,
           "station " + std::to_string(index) + " has no " + (side == 0 ? "robot" : "camera") +
               " pose file (" + partner + ")",
           "add " + partner + " beside it, or remove " + fs::path(other.path).filename().string());
    }
  }

  ImportedPoses result;
  result.robot = import_internal::MakeTable(files.front().path, LengthUnit::kMetre);
  result.camera = import_internal::MakeTable(files.front().path, LengthUnit::kMetre);
  std::vector<const VispPoseFile*> used[2];
  std::set<std::string> robot_tags;
  for (const auto& [index, station] : stations) {
    PoseTable* tables[2] = {&result.robot, &*result.camera};
    for (int side = 0; side < 2; ++side) {
      PoseRow row;
      row.pose = ReadPoseVector(*station.file[side], &row.line);
      row.id = std::to_string(index);
      tables[side]->rows.push_back(std::move(row));
      used[side].push_back(station.file[side]);
    }
    robot_tags.insert(station.name[0].tag);
  }
  const std::string format =
      "format: visp (one vpPoseVector YAML file per station: [tx ty tz tux tuy tuz], m and rad)";
  const std::string robot_files = robot_tags.size() == 1 ? "pose_" + *robot_tags.begin() + "_<i>"
                                                         : "pose_rPe_<i> / pose_fPe_<i>";
  const std::string units = import_internal::UnitNote(LengthUnit::kMetre, "as in the source");
  const std::string ids = "id: the station index <i> of the file names";
  result.robot_notes = {format,
                        SourceNote(used[0]),
                        import_internal::RobotFrameNote(),
                        "convention: " + robot_files +
                            " = rMe = T_base_gripper (vpRobot END_EFFECTOR_FRAME), t and "
                            "rotation vector tu, used as is (no inverse)",
                        units,
                        ids};
  result.camera_notes = {format,
                         SourceNote(used[1]),
                         import_internal::CameraFrameNote(),
                         "convention: pose_cPo_<i> = cMo = T_camera_target, t and rotation "
                         "vector tu, used as is (no inverse)",
                         units,
                         ids};
  return result;
}

}  // namespace hecal::io
