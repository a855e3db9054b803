#include "list_flags.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "hecal/core/error.h"

namespace hecal::cli {
namespace {

std::string Trim(const std::string& text) {
  const size_t first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  const size_t last = text.find_last_not_of(" \t");
  return text.substr(first, last - first + 1);
}

}  // namespace

std::vector<std::string> SplitList(const std::string& flag, const std::string& text) {
  std::vector<std::string> items;
  size_t start = 0;
  while (true) {
    const size_t comma = text.find(',', start);
    const std::string item =
        Trim(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (item.empty()) {
      throw InputError(flag, 0, "empty item in the list '" + text + "'",
                       "separate values with single commas, e.g. " + flag + " a,b");
    }
    items.push_back(item);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return items;
}

std::vector<int> ParseIntList(const std::string& flag, const std::string& text, int minimum,
                              int maximum) {
  std::vector<int> values;
  for (const std::string& item : SplitList(flag, text)) {
    int value = 0;
    const auto [end, error] = std::from_chars(item.data(), item.data() + item.size(), value);
    const bool integer = error == std::errc() && end == item.data() + item.size();
    if (!integer && error != std::errc::result_out_of_range) {
      throw InputError(flag, 0, "'" + item + "' is not an integer", "e.g. " + flag + " 10,20,50");
    }
    if (!integer || value < minimum || value > maximum) {
      throw InputError(
          flag, 0,
          "'" + item + "' is outside the range " + std::to_string(minimum) + " to " +
              std::to_string(maximum),
          "use values from " + std::to_string(minimum) + " to " + std::to_string(maximum));
    }
    values.push_back(value);
  }
  return values;
}

std::string MethodNames() {
  std::string names;
  for (const estimation::MethodInfo& info : estimation::AllMethods()) {
    if (!names.empty()) names += ", ";
    names += info.name;
  }
  return names;
}

std::vector<estimation::Method> ParseMethodList(const std::string& flag, const std::string& text) {
  std::vector<estimation::Method> methods;
  for (const std::string& item : SplitList(flag, text)) {
    if (item == "all") {
      for (const estimation::MethodInfo& info : estimation::AllMethods())
        methods.push_back(info.method);
      continue;
    }
    const std::optional<estimation::Method> method = estimation::ParseMethod(item);
    if (!method) {
      throw InputError(flag, 0, "unknown method '" + item + "'",
                       "use all or one or more of " + MethodNames());
    }
    methods.push_back(*method);
  }
  // Keep the first occurrence of each method.
  std::vector<estimation::Method> unique;
  for (estimation::Method m : methods) {
    if (std::find(unique.begin(), unique.end(), m) == unique.end()) unique.push_back(m);
  }
  return unique;
}

double ParseNonNegative(const std::string& flag, const std::string& text) {
  const std::string item = Trim(text);
  double value = 0.0;
  const auto [end, error] = std::from_chars(item.data(), item.data() + item.size(), value);
  if (item.empty() || error != std::errc() || end != item.data() + item.size() ||
      !std::isfinite(value) || value < 0.0) {
    throw InputError(flag, 0, "'" + text + "' is not a non-negative number",
                     "e.g. " + flag + " 0.3");
  }
  return value;
}

SigmaLevel ParseSigmaLevel(const std::string& flag, const std::string& text) {
  const size_t slash = text.find('/');
  if (slash == std::string::npos) {
    const double n = ParseNonNegative(flag, text);
    return {n, n};
  }
  return {ParseNonNegative(flag, text.substr(0, slash)),
          ParseNonNegative(flag, text.substr(slash + 1))};
}

}  // namespace hecal::cli
