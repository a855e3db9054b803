// Test support for the CLI tests: a deliberately small, independent CSV reader (split at commas,
// '#' lines kept aside, columns by name), so that the tests check hecal's output files without
// going through hecal's own reader.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "hecal/io/atomic_file.h"

namespace hecal::cli::csv_test {

struct Csv {
  std::vector<std::string> comments;  // whole lines, with '#'
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;

  bool Has(const std::string& column) const {
    return std::find(header.begin(), header.end(), column) != header.end();
  }
  size_t Index(const std::string& column) const {
    const auto it = std::find(header.begin(), header.end(), column);
    EXPECT_NE(it, header.end()) << "no column " << column;
    return static_cast<size_t>(it - header.begin());
  }
  const std::string& Text(size_t row, const std::string& column) const {
    return rows.at(row).at(Index(column));
  }
  double Number(size_t row, const std::string& column) const {
    if (!Has(column)) {
      ADD_FAILURE() << "no column " << column;
      return std::nan("");
    }
    return std::stod(Text(row, column));
  }
};

inline std::vector<std::string> SplitComma(const std::string& line) {
  std::vector<std::string> fields;
  size_t begin = 0;
  while (true) {
    const size_t comma = line.find(',', begin);
    fields.push_back(
        line.substr(begin, comma == std::string::npos ? std::string::npos : comma - begin));
    if (comma == std::string::npos) break;
    begin = comma + 1;
  }
  return fields;
}

inline Csv ParseCsv(const std::string& text) {
  Csv csv;
  std::stringstream stream(text);
  std::string line;
  while (std::getline(stream, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    if (line.front() == '#') {
      csv.comments.push_back(line);
    } else if (csv.header.empty()) {
      csv.header = SplitComma(line);
    } else {
      csv.rows.push_back(SplitComma(line));
      EXPECT_EQ(csv.rows.back().size(), csv.header.size()) << line;
    }
  }
  return csv;
}

inline Csv ReadCsv(const std::string& path) {
  return ParseCsv(io::ReadFile(path));
}

}  // namespace hecal::cli::csv_test
