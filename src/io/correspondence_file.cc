#include "hecal/io/correspondence_file.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <set>

#include "hecal/core/error.h"
#include "hecal/io/atomic_file.h"
#include "hecal/io/delimited_text.h"

namespace hecal::io {
namespace {

const std::vector<std::string> kPixelColumns = {"u1", "v1", "u2", "v2"};
const std::vector<std::string> kBearingColumns = {"x1", "y1", "z1", "x2", "y2", "z2"};

}  // namespace

CorrespondenceFile ParseCorrespondenceFile(std::string_view text, const std::string& source) {
  LineCursor cursor(text);
  std::string_view line;
  std::vector<Field> fields;
  std::string error;
  std::map<std::string, int> column;
  int header_line = 0;
  while (cursor.Next(&line)) {
    if (Trim(line).empty() || IsComment(line)) continue;
    header_line = cursor.line_number();
    if (!SplitFields(line, Separator::kComma, &fields, &error)) {
      throw InputError(source, header_line, error, "write the header as plain CSV names");
    }
    for (std::size_t i = 0; i < fields.size(); ++i) {
      const std::string name = Lowercase(Trim(FieldValue(fields[i])));
      const bool known = name == "first" || name == "second" || name == "id" ||
                         std::count(kPixelColumns.begin(), kPixelColumns.end(), name) ||
                         std::count(kBearingColumns.begin(), kBearingColumns.end(), name);
      if (!known) {
        throw InputError(source, header_line, "unknown column '" + name + "'",
                         "use first,second[,id] and u1,v1,u2,v2 (pixels) or "
                         "x1,y1,z1,x2,y2,z2 (bearings)");
      }
      if (!column.emplace(name, int(i)).second) {
        throw InputError(source, header_line, "column '" + name + "' appears twice",
                         "keep one '" + name + "' column");
      }
    }
    break;
  }
  if (header_line == 0) {
    throw InputError(source, 0, "no header and no matches", "see docs/global.md for the format");
  }
  auto has_all = [&](const std::vector<std::string>& names) {
    return std::all_of(names.begin(), names.end(), [&](auto& n) { return column.count(n) > 0; });
  };
  auto has_any = [&](const std::vector<std::string>& names) {
    return std::any_of(names.begin(), names.end(), [&](auto& n) { return column.count(n) > 0; });
  };
  for (const char* name : {"first", "second"}) {
    if (!column.count(name)) {
      throw InputError(source, header_line, std::string("missing column '") + name + "'",
                       "name the two stations of every match in columns first,second");
    }
  }
  CorrespondenceFile file;
  const bool pixels = has_any(kPixelColumns), bearings = has_any(kBearingColumns);
  if (pixels == bearings) {
    throw InputError(
        source, header_line,
        pixels ? "both pixel (u1..v2) and bearing (x1..z2) columns" : "no coordinate columns",
        "give u1,v1,u2,v2 in pixels or x1,y1,z1,x2,y2,z2 as bearings, not both");
  }
  const std::vector<std::string>& coordinates = pixels ? kPixelColumns : kBearingColumns;
  if (!has_all(coordinates)) {
    throw InputError(source, header_line, "incomplete coordinate columns",
                     pixels ? "give all of u1,v1,u2,v2" : "give all of x1,y1,z1,x2,y2,z2");
  }
  file.pixels = pixels;
  std::map<std::pair<std::string, std::string>, int> motion_index;
  std::vector<std::set<int>> ids_seen;
  while (cursor.Next(&line)) {
    if (Trim(line).empty() || IsComment(line)) continue;
    const int number = cursor.line_number();
    if (!SplitFields(line, Separator::kComma, &fields, &error)) {
      throw InputError(source, number, error, "quote fields as RFC 4180 does");
    }
    if (fields.size() != column.size()) {
      throw InputError(source, number,
                       std::to_string(fields.size()) + " fields for " +
                           std::to_string(column.size()) + " columns",
                       "give one value per header column");
    }
    auto value = [&](const std::string& name) {
      double x = 0.0;
      const std::string_view field = Trim(fields[column[name]].text);
      if (!ParseDouble(field, &x) || !std::isfinite(x)) {
        throw InputError(
            source, number,
            "'" + std::string(field) + "' in column " + name + " is not a finite number",
            "write numbers with '.' as the decimal separator");
      }
      return x;
    };
    const std::string first(Trim(FieldValue(fields[column["first"]])));
    const std::string second(Trim(FieldValue(fields[column["second"]])));
    if (first.empty() || second.empty() || first == second) {
      throw InputError(source, number,
                       "the stations '" + first + "' and '" + second + "' do not name a motion",
                       "give two different stations in first and second");
    }
    const auto [it, inserted] =
        motion_index.emplace(std::make_pair(first, second), int(file.motions.size()));
    if (inserted) {
      file.motions.push_back({first, second, number, {}, {}, {}, {}});
      ids_seen.emplace_back();
    }
    CorrespondenceMotion& motion = file.motions[it->second];
    int id = int(motion.ids.size());
    if (column.count("id")) {
      const double raw = value("id");
      if (raw != std::floor(raw) || std::abs(raw) > 1e9) {
        throw InputError(
            source, number,
            "id " + std::string(Trim(fields[column["id"]].text)) + " is not an integer",
            "number the matches with integers");
      }
      id = int(raw);
    }
    if (!ids_seen[it->second].insert(id).second) {
      throw InputError(
          source, number,
          "id " + std::to_string(id) + " appears twice in the motion " + first + " -> " + second,
          "give every match of a motion its own id");
    }
    Eigen::Vector3d p1, p2;
    if (pixels) {
      p1 = Eigen::Vector3d(value("u1"), value("v1"), 1.0);
      p2 = Eigen::Vector3d(value("u2"), value("v2"), 1.0);
    } else {
      p1 = Eigen::Vector3d(value("x1"), value("y1"), value("z1"));
      p2 = Eigen::Vector3d(value("x2"), value("y2"), value("z2"));
      if (p1.norm() == 0.0 || p2.norm() == 0.0) {
        throw InputError(source, number, "a bearing of length 0",
                         "give the ray's direction (any non-zero length)");
      }
      p1.normalize();
      p2.normalize();
    }
    motion.ids.push_back(id);
    motion.first_points.push_back(p1);
    motion.second_points.push_back(p2);
    motion.lines.push_back(number);
  }
  if (file.motions.empty()) {
    throw InputError(source, header_line, "a header but no matches", "add one row per point match");
  }
  return file;
}

CorrespondenceFile ReadCorrespondenceFile(const std::string& path) {
  return ParseCorrespondenceFile(ReadFile(path), path);
}

}  // namespace hecal::io
