// The command line's own rules: see bounds.h.
#include "bounds.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "hecal/hecal.h"
#include "list_flags.h"

namespace hecal::cli {
namespace {

// The whole-number rule of bounds.h for one item: its value, or an InputError.
template <class T>
T WholeNumber(const std::string& flag, const std::string& text) {
  const std::string_view item = io::Trim(text);
  T value = 0;
  const auto [end, error] = std::from_chars(item.data(), item.data() + item.size(), value);
  if (!item.empty() && error == std::errc() && end == item.data() + item.size()) return value;
  const bool show_range = std::is_unsigned_v<T> || error == std::errc::result_out_of_range;
  const std::string range = " from " + std::to_string(std::numeric_limits<T>::min()) + " to " +
                            std::to_string(std::numeric_limits<T>::max());
  throw InputError(flag, 0,
                   "must be a whole number" + (show_range ? range : " in decimal digits") +
                       ", got '" + text + "'",
                   "give a whole number" + (show_range ? " in that range" : std::string()) +
                       ", e.g. " + flag + " 1");
}

}  // namespace

template <class T>
CLI::Option* AddWholeNumber(CLI::App& command, const std::string& flag, T& value,
                            const std::string& help) {
  return command.add_option(flag, value, help)->transform([flag](const std::string& text) {
    return std::to_string(WholeNumber<T>(flag, text));
  });
}

template CLI::Option* AddWholeNumber(CLI::App&, const std::string&, int&, const std::string&);
template CLI::Option* AddWholeNumber(CLI::App&, const std::string&, std::int64_t&,
                                     const std::string&);
template CLI::Option* AddWholeNumber(CLI::App&, const std::string&, std::uint64_t&,
                                     const std::string&);

CLI::Option* AddSeedFlag(CLI::App& command, std::uint64_t& seed) {
  return AddWholeNumber(command, "--seed", seed, "Random seed (0 to 2^64-1)")
      ->capture_default_str();
}

CLI::Option* AddWholeNumberList(CLI::App& command, const std::string& flag,
                                std::vector<int>& values, const std::string& help) {
  return command.add_option_function<std::string>(
      flag,
      [flag, &values](const std::string& text) {
        values.clear();
        for (const std::string& item : SplitList(flag, text)) {
          values.push_back(WholeNumber<int>(flag, item));
        }
      },
      help);
}

std::vector<double> ParseNumberList(const std::string& flag, const std::string& text,
                                    std::size_t count, const std::string& what) {
  const std::string give = "give " +
                           (count == kAnyCount ? std::string() : std::to_string(count) + " ") +
                           "comma-separated numbers " + what;
  std::vector<double> values;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    const std::string part =
        text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    double value = 0.0;
    if (!io::ParseDouble(io::Trim(part), &value) || !std::isfinite(value)) {
      throw InputError(flag, 0, "'" + part + "' is not a finite number (in '" + text + "')", give);
    }
    values.push_back(value);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (count != kAnyCount && values.size() != count) {
    throw InputError(flag, 0,
                     "expected " + std::to_string(count) + " numbers, got " +
                         std::to_string(values.size()) + " ('" + text + "')",
                     give);
  }
  return values;
}

double ParseNumber(const std::string& flag, const std::string& text, const std::string& what) {
  return ParseNumberList(flag, text, 1, what).front();
}

}  // namespace hecal::cli
