#include "hecal/pose/target.h"

#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "hecal/core/error.h"

namespace hecal::pose {
namespace {

constexpr std::array<TargetType, 8> kTypes = {
    TargetType::kChessboard,   TargetType::kCharuco, TargetType::kArucoGrid,
    TargetType::kAprilTagGrid, TargetType::kCircles, TargetType::kAsymmetricCircles,
    TargetType::kAruco,        TargetType::kAprilTag};

constexpr std::array<TargetField, 10> kFields = {
    TargetField::kCols,    TargetField::kRows,       TargetField::kSquare, TargetField::kMarker,
    TargetField::kSpacing, TargetField::kDictionary, TargetField::kFamily, TargetField::kFirstId,
    TargetField::kId,      TargetField::kSize};

// cv::aruco::PREDEFINED_DICTIONARY_NAME of OpenCV 4.6 (opencv2/aruco/dictionary.hpp), in enum
// order; sizes are the dictionaries' code counts (the number in the name; ARUCO_ORIGINAL 1024,
// the AprilTag ones as in their comments). target_opencv_test checks both against OpenCV.
constexpr std::array<MarkerDictionary, 21> kArucoDictionaries = {{
    {"DICT_4X4_50", 50},        {"DICT_4X4_100", 100},         {"DICT_4X4_250", 250},
    {"DICT_4X4_1000", 1000},    {"DICT_5X5_50", 50},           {"DICT_5X5_100", 100},
    {"DICT_5X5_250", 250},      {"DICT_5X5_1000", 1000},       {"DICT_6X6_50", 50},
    {"DICT_6X6_100", 100},      {"DICT_6X6_250", 250},         {"DICT_6X6_1000", 1000},
    {"DICT_7X7_50", 50},        {"DICT_7X7_100", 100},         {"DICT_7X7_250", 250},
    {"DICT_7X7_1000", 1000},    {"DICT_ARUCO_ORIGINAL", 1024}, {"DICT_APRILTAG_16h5", 30},
    {"DICT_APRILTAG_25h9", 35}, {"DICT_APRILTAG_36h10", 2320}, {"DICT_APRILTAG_36h11", 587},
}};

// libapriltag 3.3's families (dpkg -L libapriltag-dev: tag*.h) with their ncodes;
// target_opencv_test checks them against the library.
constexpr std::array<MarkerDictionary, 9> kAprilTagFamilies = {{
    {"tag16h5", 30},
    {"tag25h9", 35},
    {"tag36h10", 2320},
    {"tag36h11", 587},
    {"tagCircle21h7", 38},
    {"tagCircle49h12", 65535},
    {"tagCustom48h12", 42211},
    {"tagStandard41h12", 2115},
    {"tagStandard52h13", 48714},
}};

constexpr int kMaxCount = 1000;  // cols and rows: bounds the allocation, far above real boards

const MarkerDictionary* FindByName(std::span<const MarkerDictionary> list, std::string_view name) {
  for (const MarkerDictionary& entry : list) {
    if (entry.name == name) return &entry;
  }
  return nullptr;
}

std::string Names(std::span<const MarkerDictionary> list) {
  std::string names;
  for (const MarkerDictionary& entry : list) {
    if (!names.empty()) names += ", ";
    names += entry.name;
  }
  return names;
}

bool IsSet(const TargetSpec& target, TargetField field) {
  switch (field) {
    case TargetField::kCols:
      return target.cols != 0;
    case TargetField::kRows:
      return target.rows != 0;
    case TargetField::kSquare:
      return target.square != 0.0;
    case TargetField::kMarker:
      return target.marker != 0.0;
    case TargetField::kSpacing:
      return target.spacing != 0.0;
    case TargetField::kDictionary:
      return !target.dictionary.empty();
    case TargetField::kFamily:
      return !target.family.empty();
    case TargetField::kFirstId:
      return target.first_id != 0;
    case TargetField::kId:
      return target.id != 0;
    case TargetField::kSize:
      return target.size != 0.0;
  }
  return false;
}

// A length for messages, with up to 6 significant digits ("0.0176 m").
std::string Metres(double value) {
  std::ostringstream text;
  text << value << " m";
  return text.str();
}

// "chessboard targets", for messages.
std::string TypeText(const TargetSpec& target) {
  return std::string(TargetTypeName(target.type)) + " targets";
}

// What cols and rows count for a type.
const char* CountedThing(TargetType type) {
  switch (type) {
    case TargetType::kCharuco:
      return "squares";
    case TargetType::kArucoGrid:
    case TargetType::kAprilTagGrid:
      return "markers";
    case TargetType::kChessboard:
    case TargetType::kCircles:
    case TargetType::kAsymmetricCircles:
    case TargetType::kAruco:
    case TargetType::kAprilTag:
      break;
  }
  return "points";
}

bool IsMarkerGrid(TargetType type) {
  return type == TargetType::kArucoGrid || type == TargetType::kAprilTagGrid;
}

std::optional<TargetProblem> CheckCount(const TargetSpec& target, TargetField field, int value) {
  const int minimum = target.type == TargetType::kCharuco ? 3 : 2;
  if (value >= minimum && value <= kMaxCount) return std::nullopt;
  const std::string thing = CountedThing(target.type);
  return TargetProblem{
      field,
      std::string(TargetFieldName(field)) + " is " + std::to_string(value) + "; " +
          TypeText(target) + " need " + std::to_string(minimum) + " to " +
          std::to_string(kMaxCount) + " " + thing + " along " +
          (field == TargetField::kCols ? "x" : "y"),
      target.type == TargetType::kCharuco
          ? "count the squares, not the inner corners (with fewer than 3 squares the corners "
            "lie on one line)"
      : IsMarkerGrid(target.type) && value == 1
          ? std::string("for one marker use type: ") +
                (target.type == TargetType::kArucoGrid ? "aruco with dictionary"
                                                       : "apriltag with family") +
                ", id and size (docs/targets.md, single tags); for a grid, count the markers "
                "along " +
                (field == TargetField::kCols ? "x" : "y")
          : "count the " + thing + " along " + (field == TargetField::kCols ? "x" : "y")};
}

std::optional<TargetProblem> CheckLength(const TargetSpec& target, TargetField field,
                                         double value) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    return TargetProblem{
        field,
        std::string(TargetFieldName(field)) + " must be a positive length for " + TypeText(target),
        "give the measured " + std::string(TargetFieldName(field)) +
            " in metres (or set units: mm)"};
  }
  return std::nullopt;
}

std::optional<TargetProblem> CheckIds(const TargetSpec& target, TargetField field,
                                      std::span<const MarkerDictionary> list,
                                      const std::string& name, const char* what) {
  const MarkerDictionary* entry = FindByName(list, name);
  if (entry == nullptr) {
    return TargetProblem{field, "unknown " + std::string(what) + " '" + name + "'",
                         "use one of " + Names(list)};
  }
  if (IsSingleTag(target.type)) {
    if (target.id >= entry->size) {
      return TargetProblem{TargetField::kId,
                           "id " + std::to_string(target.id) + " is not in " + name +
                               ", whose ids are 0 to " + std::to_string(entry->size - 1),
                           "give the id printed with the tag, and the " + std::string(what) +
                               " it was generated from"};
    }
    return std::nullopt;
  }
  const long last = static_cast<long>(target.first_id) + MarkerCount(target);
  if (last > entry->size) {
    return TargetProblem{target.first_id > 0 ? TargetField::kFirstId : field,
                         "the target needs marker ids " + std::to_string(target.first_id) + " to " +
                             std::to_string(last - 1) + " but " + name + " has only " +
                             std::to_string(entry->size) + " ids",
                         "use a larger dictionary or a smaller board"};
  }
  return std::nullopt;
}

}  // namespace

std::string_view TargetTypeName(TargetType type) {
  switch (type) {
    case TargetType::kChessboard:
      return "chessboard";
    case TargetType::kCharuco:
      return "charuco";
    case TargetType::kArucoGrid:
      return "aruco_grid";
    case TargetType::kAprilTagGrid:
      return "apriltag_grid";
    case TargetType::kCircles:
      return "circles";
    case TargetType::kAsymmetricCircles:
      return "acircles";
    case TargetType::kAruco:
      return "aruco";
    case TargetType::kAprilTag:
      return "apriltag";
  }
  throw std::invalid_argument("TargetTypeName: unknown TargetType value");
}

std::optional<TargetType> ParseTargetType(std::string_view name) {
  for (const TargetType type : kTypes) {
    if (TargetTypeName(type) == name) return type;
  }
  return std::nullopt;
}

std::span<const TargetType> TargetTypes() {
  return kTypes;
}

std::string_view TargetFieldName(TargetField field) {
  switch (field) {
    case TargetField::kCols:
      return "cols";
    case TargetField::kRows:
      return "rows";
    case TargetField::kSquare:
      return "square";
    case TargetField::kMarker:
      return "marker";
    case TargetField::kSpacing:
      return "spacing";
    case TargetField::kDictionary:
      return "dictionary";
    case TargetField::kFamily:
      return "family";
    case TargetField::kFirstId:
      return "first_id";
    case TargetField::kId:
      return "id";
    case TargetField::kSize:
      return "size";
  }
  throw std::invalid_argument("TargetFieldName: unknown TargetField value");
}

std::span<const TargetField> TargetFields() {
  return kFields;
}

FieldUse TargetFieldUse(TargetType type, TargetField field) {
  const auto required_if = [](bool condition) {
    return condition ? FieldUse::kRequired : FieldUse::kUnused;
  };
  const bool grid = type == TargetType::kArucoGrid || type == TargetType::kAprilTagGrid;
  const bool tag = IsSingleTag(type);
  switch (field) {
    case TargetField::kCols:
    case TargetField::kRows:
      return required_if(!tag);
    case TargetField::kSquare:
      return required_if(!grid && !tag);
    case TargetField::kMarker:
      return required_if(type == TargetType::kCharuco || grid);
    case TargetField::kSpacing:
      return required_if(grid);
    case TargetField::kDictionary:
      return required_if(type == TargetType::kCharuco || type == TargetType::kArucoGrid ||
                         type == TargetType::kAruco);
    case TargetField::kFamily:
      return required_if(type == TargetType::kAprilTagGrid || type == TargetType::kAprilTag);
    case TargetField::kFirstId:
      return grid ? FieldUse::kOptional : FieldUse::kUnused;
    case TargetField::kId:
    case TargetField::kSize:
      return required_if(tag);
  }
  throw std::invalid_argument("TargetFieldUse: unknown TargetField value");
}

std::span<const MarkerDictionary> ArucoDictionaries() {
  return kArucoDictionaries;
}
std::span<const MarkerDictionary> AprilTagFamilies() {
  return kAprilTagFamilies;
}

bool IsSingleTag(TargetType type) {
  return type == TargetType::kAruco || type == TargetType::kAprilTag;
}

int MarkerCount(const TargetSpec& target) {
  switch (target.type) {
    case TargetType::kCharuco:
      return target.cols * target.rows / 2;
    case TargetType::kArucoGrid:
    case TargetType::kAprilTagGrid:
      return target.cols * target.rows;
    case TargetType::kAruco:
    case TargetType::kAprilTag:
      return 1;
    case TargetType::kChessboard:
    case TargetType::kCircles:
    case TargetType::kAsymmetricCircles:
      return 0;
  }
  return 0;
}

int PointCount(const TargetSpec& target) {
  switch (target.type) {
    case TargetType::kCharuco:
      return (target.cols - 1) * (target.rows - 1);
    case TargetType::kArucoGrid:
    case TargetType::kAprilTagGrid:
      return 4 * target.cols * target.rows;
    case TargetType::kAruco:
    case TargetType::kAprilTag:
      return 4;
    case TargetType::kChessboard:
    case TargetType::kCircles:
    case TargetType::kAsymmetricCircles:
      return target.cols * target.rows;
  }
  return 0;
}

std::optional<TargetProblem> CheckTarget(const TargetSpec& target) {
  for (const TargetField field : kFields) {
    if (TargetFieldUse(target.type, field) == FieldUse::kUnused && IsSet(target, field)) {
      return TargetProblem{
          field, std::string(TargetFieldName(field)) + " does not apply to " + TypeText(target),
          "remove it, or choose the target type that has it"};
    }
  }
  if (!IsSingleTag(target.type)) {
    if (auto problem = CheckCount(target, TargetField::kCols, target.cols)) return problem;
    if (auto problem = CheckCount(target, TargetField::kRows, target.rows)) return problem;
  }
  const std::pair<TargetField, double> lengths[] = {{TargetField::kSquare, target.square},
                                                    {TargetField::kMarker, target.marker},
                                                    {TargetField::kSpacing, target.spacing},
                                                    {TargetField::kSize, target.size}};
  for (const auto& [field, value] : lengths) {
    if (TargetFieldUse(target.type, field) != FieldUse::kRequired) continue;
    if (auto problem = CheckLength(target, field, value)) return problem;
  }
  if (target.type == TargetType::kCharuco && !(target.marker < target.square)) {
    return TargetProblem{TargetField::kMarker,
                         "the ChArUco marker (" + Metres(target.marker) +
                             ") must be smaller than the square (" + Metres(target.square) + ")",
                         "measure the marker's black border, inside its white square"};
  }
  if (target.type == TargetType::kAsymmetricCircles && target.rows % 2 == 0) {
    return TargetProblem{TargetField::kRows,
                         "an asymmetric circle grid with an even number of rows (" +
                             std::to_string(target.rows) +
                             ") looks the same after a half turn, and OpenCV's findCirclesGrid "
                             "does not number it consistently",
                         "use a grid with an odd number of rows (OpenCV's pattern is 4 x 11)"};
  }
  if (target.first_id < 0) {
    return TargetProblem{TargetField::kFirstId,
                         "first_id is " + std::to_string(target.first_id) + ", not an id",
                         "give the id of the top-left marker (0 or more)"};
  }
  if (target.id < 0) {
    return TargetProblem{TargetField::kId, "id is " + std::to_string(target.id) + ", not an id",
                         "give the id printed with the tag (0 or more)"};
  }
  if (TargetFieldUse(target.type, TargetField::kDictionary) == FieldUse::kRequired) {
    return CheckIds(target, TargetField::kDictionary, kArucoDictionaries, target.dictionary,
                    "ArUco dictionary");
  }
  if (TargetFieldUse(target.type, TargetField::kFamily) == FieldUse::kRequired) {
    return CheckIds(target, TargetField::kFamily, kAprilTagFamilies, target.family,
                    "AprilTag family");
  }
  return std::nullopt;
}

std::vector<ObjectPoint> ObjectPoints(const TargetSpec& target) {
  if (const std::optional<TargetProblem> problem = CheckTarget(target)) {
    throw InputError("TargetSpec." + std::string(TargetFieldName(problem->field)), 0,
                     problem->problem, problem->fix);
  }
  std::vector<ObjectPoint> points;
  points.reserve(static_cast<size_t>(PointCount(target)));
  const auto add = [&points](double x, double y) {
    points.push_back({static_cast<int>(points.size()), Eigen::Vector3d(x, y, 0.0)});
  };
  switch (target.type) {
    case TargetType::kChessboard:
    case TargetType::kCircles:
      for (int r = 0; r < target.rows; ++r) {
        for (int c = 0; c < target.cols; ++c) add(c * target.square, r * target.square);
      }
      break;
    case TargetType::kAsymmetricCircles:
      for (int r = 0; r < target.rows; ++r) {
        for (int c = 0; c < target.cols; ++c) {
          add((2 * c + r % 2) * target.square, r * target.square);
        }
      }
      break;
    case TargetType::kCharuco:
      for (int r = 1; r < target.rows; ++r) {
        for (int c = 1; c < target.cols; ++c) add(c * target.square, r * target.square);
      }
      break;
    case TargetType::kArucoGrid:
    case TargetType::kAprilTagGrid: {
      const double pitch = target.marker + target.spacing;
      for (int r = 0; r < target.rows; ++r) {
        for (int c = 0; c < target.cols; ++c) {
          const double x = c * pitch;
          const double y = r * pitch;
          add(x, y);
          add(x + target.marker, y);
          add(x + target.marker, y + target.marker);
          add(x, y + target.marker);
        }
      }
      break;
    }
    case TargetType::kAruco:
    case TargetType::kAprilTag: {
      const double half = target.size / 2.0;
      add(-half, -half);
      add(half, -half);
      add(half, half);
      add(-half, half);
      break;
    }
  }
  return points;
}

}  // namespace hecal::pose
