// Time stamps of images (stamp_file.h).
#include "hecal/io/stamp_file.h"

#include <cmath>
#include <filesystem>
#include <vector>

#include "hecal/core/error.h"
#include "hecal/io/atomic_file.h"
#include "hecal/io/delimited_text.h"

namespace hecal::io {

std::map<std::string, double> ParseStampFile(std::string_view text, const std::string& source) {
  LineCursor cursor(text);
  std::string_view line;
  std::vector<Field> fields;
  std::string error;
  int image_column = -1, stamp_column = -1;
  Separator separator = Separator::kComma;
  std::map<std::string, double> stamps;
  std::map<std::string, int> first_line;
  while (cursor.Next(&line)) {
    if (IsBlank(line) || IsComment(line)) continue;
    const int at = cursor.line_number();
    if (image_column < 0) {
      separator = DetectSeparator(line);
      if (!SplitFields(line, separator, &fields, &error))
        throw InputError(source, at, error, "write the header as image,stamp");
      for (size_t k = 0; k < fields.size(); ++k) {
        const std::string name = Lowercase(Trim(FieldValue(fields[k])));
        if (name == "image" || name == "file" || name == "id") image_column = static_cast<int>(k);
        if (name == "stamp") stamp_column = static_cast<int>(k);
      }
      if (image_column < 0 || stamp_column < 0) {
        throw InputError(source, at, "the header has no image and stamp columns",
                         "start the file with the header image,stamp (image: the file name or "
                         "stem, stamp: seconds)");
      }
      continue;
    }
    if (!SplitFields(line, separator, &fields, &error))
      throw InputError(source, at, error, "write one image,stamp pair per line");
    const size_t needed = static_cast<size_t>(std::max(image_column, stamp_column)) + 1;
    if (fields.size() < needed) {
      throw InputError(source, at, "has " + std::to_string(fields.size()) + " fields",
                       "write one image,stamp pair per line, as the header");
    }
    const std::string stem =
        std::filesystem::path(std::string(Trim(FieldValue(fields[static_cast<size_t>(image_column)]))))
            .stem()
            .string();
    double stamp = 0.0;
    if (!ParseDouble(Trim(FieldValue(fields[static_cast<size_t>(stamp_column)])), &stamp) ||
        !std::isfinite(stamp)) {
      throw InputError(source, at, "the stamp of " + stem + " is not a finite number",
                       "write the stamp in seconds, e.g. 1634567890.123456");
    }
    if (stem.empty()) throw InputError(source, at, "has no image name", "name the image file");
    if (const auto [it, fresh] = first_line.emplace(stem, at); !fresh) {
      throw InputError(source, at, stem + " is stamped twice (first on line " +
                                       std::to_string(it->second) + ")",
                       "keep one row per image");
    }
    stamps[stem] = stamp;
  }
  if (image_column < 0) {
    throw InputError(source, 0, "is empty", "write the header image,stamp and one row per image");
  }
  return stamps;
}

std::map<std::string, double> ReadStampFile(const std::string& path) {
  return ParseStampFile(ReadFile(path), path);
}

double StampFromFileName(const std::string& stem) {
  double stamp = 0.0;
  if (!ParseDouble(stem, &stamp) || !std::isfinite(stamp)) {
    throw InputError(stem, 0, "the image's name is not a time stamp",
                     "name the images by their stamps (e.g. 1634567890.123456.png) or give "
                     "--stamps stamps.csv with an image,stamp row per image");
  }
  return stamp;
}

}  // namespace hecal::io
