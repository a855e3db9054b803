#include "hecal/io/import_tabb.h"

#include <algorithm>
#include <set>

#include "import_internal.h"

namespace hecal::io {
namespace {

using import_internal::Fail;
using import_internal::Number;
using import_internal::Origin;
using import_internal::TextLine;

constexpr long kMaxPoses = 1000000;
constexpr int kCameraFields = 30;
constexpr double kMetresPerMillimetre = 1e-3;

// Non-blank lines (Tabb's files have no comments, but '#' lines are skipped as elsewhere).
std::vector<TextLine> DataLines(std::string_view text) {
  std::vector<TextLine> lines = import_internal::SplitLines(text);
  lines.erase(std::remove_if(lines.begin(), lines.end(),
                             [](const TextLine& line) {
                               return import_internal::IsBlankLine(line.text) ||
                                      import_internal::IsCommentLine(line.text);
                             }),
              lines.end());
  return lines;
}

bool LooksLikeImageName(std::string_view token) {
  return !token.empty() && !import_internal::ParseNumber(token).has_value();
}

// The first data line: the number of poses N.
long ReadCount(const std::vector<TextLine>& lines, const std::string& source,
               const std::string& what) {
  if (lines.empty()) Fail(source, 0, "the file is empty", "give " + what);
  const std::vector<std::string_view> tokens = import_internal::SplitTokens(lines[0].text);
  const std::optional<Number> count =
      tokens.size() == 1 ? import_internal::ParseNumber(tokens[0]) : std::nullopt;
  if (!count || !(count->value >= 1.0) || count->value > static_cast<double>(kMaxPoses) ||
      count->value != static_cast<double>(static_cast<long>(count->value))) {
    Fail(source, lines[0].number,
         "the first line should be the number of poses N, found " +
             import_internal::Quoted(lines[0].text),
         "give " + what);
  }
  return static_cast<long>(count->value);
}

std::vector<PoseRow> ReadRobot(std::string_view text, const std::string& source,
                               RotationInput* rotations) {
  const std::string what = "Tabb's robot_cali.txt: N, then N 4x4 matrices (B_i = T_gripper_base)";
  const std::vector<TextLine> lines = DataLines(text);
  const long count = ReadCount(lines, source, what);
  const long rows = static_cast<long>(lines.size()) - 1;
  std::vector<PoseRow> poses;
  for (long block = 0; block * 4 < rows; ++block) {
    double values[16];
    double rounding = 0.0;
    const TextLine& first = lines[static_cast<size_t>(1 + 4 * block)];
    const long available = std::min<long>(4, rows - 4 * block);
    for (int r = 0; r < available; ++r) {
      const TextLine& line = lines[static_cast<size_t>(1 + 4 * block + r)];
      const std::vector<std::string_view> tokens = import_internal::SplitTokens(line.text);
      if (tokens.size() != 4) {
        const bool camera_file = !tokens.empty() && LooksLikeImageName(tokens[0]);
        Fail(source, line.number,
             "expected 4 numbers (row " + std::to_string(r + 1) + " of pose " +
                 std::to_string(block) + "'s 4x4 matrix), found " + std::to_string(tokens.size()) +
                 " fields",
             camera_file ? "this looks like cali.txt (camera poses): give robot_cali.txt first, "
                           "cali.txt second"
                         : "write each pose as 4 rows of 4 numbers");
      }
      const std::vector<Number> numbers =
          import_internal::ParseNumbers(tokens, source, line.number);
      for (int c = 0; c < 4; ++c) {
        values[4 * r + c] = numbers[static_cast<size_t>(c)].value;
        if (r < 3 && c < 3) rounding = std::max(rounding, numbers[static_cast<size_t>(c)].rounding);
      }
    }
    if (available < 4) {
      Fail(source, first.number,
           "pose " + std::to_string(block) + " has only " + std::to_string(available) +
               " of its 4 matrix rows (the file ends)",
           "give every pose as 4 rows of 4 numbers");
    }
    PoseRow row;
    const Pose T_gripper_base = import_internal::PoseFromRowMajor(
        values, 16, rounding, kMetresPerMillimetre,
        Origin{source, first.number,
               "pose " + std::to_string(block) + " (B_" + std::to_string(block) + ")"},
        rotations);
    row.pose = T_gripper_base.inverse();
    row.line = first.number;
    poses.push_back(std::move(row));
  }
  if (static_cast<long>(poses.size()) != count) {
    Fail(source, lines[0].number,
         "N is " + std::to_string(count) + " but the file has " + std::to_string(poses.size()) +
             " poses",
         "make the first line the number of 4x4 matrices that follow");
  }
  return poses;
}

struct CameraLine {
  PoseRow row;
  ImportedIntrinsics intrinsics;
};

std::vector<CameraLine> ReadCamera(std::string_view text, const std::string& source,
                                   RotationInput* rotations) {
  const std::string what =
      "Tabb's cali.txt: N, then one line per image: name, K (9), R (9), t (3), distortion (5), "
      "0 0 0";
  const std::vector<TextLine> lines = DataLines(text);
  const long count = ReadCount(lines, source, what);
  std::vector<CameraLine> cameras;
  std::set<std::string> ids;
  for (size_t index = 1; index < lines.size(); ++index) {
    const TextLine& line = lines[index];
    const std::vector<std::string_view> tokens = import_internal::SplitTokens(line.text);
    if (tokens.size() != kCameraFields) {
      const bool robot_file = tokens.size() == 4 && !LooksLikeImageName(tokens[0]);
      Fail(source, line.number,
           "expected 30 fields (image name, K 9, R 9, t 3, distortion 5, 0 0 0), found " +
               std::to_string(tokens.size()),
           robot_file ? "this looks like robot_cali.txt (4x4 robot poses): give robot_cali.txt "
                        "first, cali.txt second"
                      : "write one image per line in Tabb's cali.txt layout");
    }
    if (!LooksLikeImageName(tokens[0])) {
      Fail(source, line.number,
           "the first field should be the image name, found " + import_internal::Quoted(tokens[0]),
           "write one image per line: imageK.png fx 0 cx ...");
    }
    const std::vector<std::string_view> number_tokens(tokens.begin() + 1, tokens.end());
    const std::vector<Number> numbers =
        import_internal::ParseNumbers(number_tokens, source, line.number);
    const auto value = [&](int field) { return numbers[static_cast<size_t>(field)].value; };
    for (size_t k = 0; k < numbers.size(); ++k) {
      if (!std::isfinite(numbers[k].value)) {
        Fail(source, line.number,
             "field " + std::to_string(k + 2) + " is not finite (" +
                 import_internal::Quoted(number_tokens[k]) + ")",
             "replace it with a finite value or remove the image");
      }
    }
    // K = [fx s cx; 0 fy cy; 0 0 1] (fields 2..10).
    if (value(3) != 0.0 || value(6) != 0.0 || value(7) != 0.0 || value(8) != 1.0) {
      Fail(source, line.number, "the camera matrix (fields 2-10) is not [fx 0 cx 0 fy cy 0 0 1]",
           "write K row-major after the image name");
    }
    double rotation[9];
    double translation[3];
    double rounding = 0.0;
    for (int k = 0; k < 9; ++k) {
      rotation[k] = value(9 + k);
      rounding = std::max(rounding, numbers[static_cast<size_t>(9 + k)].rounding);
    }
    for (int k = 0; k < 3; ++k) translation[k] = value(18 + k);
    CameraLine camera;
    const std::string id = import_internal::FileStem(tokens[0]);
    if (id.empty()) {
      Fail(source, line.number,
           "image name " + import_internal::Quoted(tokens[0]) + " has no file name",
           "start the line with the image file name, e.g. image0.png");
    }
    if (!ids.insert(id).second) {
      Fail(source, line.number, "image " + import_internal::Quoted(id) + " appears twice",
           "list every image once");
    }
    camera.row.pose = import_internal::PoseFromRotationAndTranslation(
        rotation, translation, rounding, kMetresPerMillimetre,
        Origin{source, line.number, "the pose of " + std::string(tokens[0])}, rotations);
    camera.row.id = id;
    camera.row.line = line.number;
    camera.intrinsics.fx = value(0);
    camera.intrinsics.cx = value(2);
    camera.intrinsics.fy = value(4);
    camera.intrinsics.cy = value(5);
    camera.intrinsics.distortion = {value(21), value(22), value(23), value(24), value(25)};
    camera.intrinsics.source = source;
    cameras.push_back(std::move(camera));
  }
  if (static_cast<long>(cameras.size()) != count) {
    Fail(source, lines[0].number,
         "N is " + std::to_string(count) + " but the file has " + std::to_string(cameras.size()) +
             " image lines",
         "make the first line the number of image lines that follow");
  }
  return cameras;
}

bool SameIntrinsics(const ImportedIntrinsics& a, const ImportedIntrinsics& b) {
  return a.fx == b.fx && a.fy == b.fy && a.cx == b.cx && a.cy == b.cy &&
         a.distortion == b.distortion;
}

}  // namespace

ImportedPoses ParseTabb(std::string_view robot_text, const std::string& robot_source,
                        std::string_view camera_text, const std::string& camera_source) {
  RotationInput robot_rotations(robot_source);
  RotationInput camera_rotations(camera_source);
  std::vector<PoseRow> robot = ReadRobot(robot_text, robot_source, &robot_rotations);
  std::vector<CameraLine> cameras = ReadCamera(camera_text, camera_source, &camera_rotations);
  if (robot.size() != cameras.size()) {
    Fail(robot_source, 0,
         "has " + std::to_string(robot.size()) + " robot poses but " + camera_source + " has " +
             std::to_string(cameras.size()) + " camera poses",
         "give one robot pose per image (block i of robot_cali.txt pairs with line i of "
         "cali.txt)");
  }

  ImportedPoses result;
  result.robot = import_internal::MakeTable(robot_source, LengthUnit::kMillimetre);
  result.camera = import_internal::MakeTable(camera_source, LengthUnit::kMillimetre);
  bool one_camera_model = true;
  for (size_t i = 0; i < robot.size(); ++i) {
    robot[i].id = cameras[i].row.id;
    result.robot.rows.push_back(std::move(robot[i]));
    result.camera->rows.push_back(cameras[i].row);
    one_camera_model =
        one_camera_model && SameIntrinsics(cameras[i].intrinsics, cameras[0].intrinsics);
  }
  if (one_camera_model) result.intrinsics = cameras[0].intrinsics;
  result.robot.warnings = robot_rotations.Notes();
  result.camera->warnings = camera_rotations.Notes();

  const std::string format = "format: tabb (Tabb & Ahmad Yousef robot_cali.txt + cali.txt)";
  const std::string units = import_internal::UnitNote(LengthUnit::kMillimetre, "as in the source");
  const std::string ids =
      "id: the image file stem from cali.txt; robot_cali.txt block i pairs "
      "with cali.txt line i";
  result.robot_notes = {format,
                        "source: " + robot_source,
                        import_internal::RobotFrameNote(),
                        "convention: the file holds B_i = T_gripper_base (the base in the "
                        "gripper frame); each pose was INVERTED to T_base_gripper",
                        units,
                        ids};
  result.camera_notes = {format,
                         "source: " + camera_source,
                         import_internal::CameraFrameNote(),
                         "convention: R, t of each line = T_camera_target (chessboard in the "
                         "camera frame), used as is (no inverse)",
                         units,
                         ids};
  if (!one_camera_model) {
    result.camera_notes.push_back("intrinsics: not the same on every line of " + camera_source);
  }
  return result;
}

}  // namespace hecal::io
