// The bounds of the command line: see bounds.h.
#include "bounds.h"

#include <charconv>
#include <limits>

#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/io/delimited_text.h"

namespace hecal::cli {
namespace {

std::string Number(double value) {
  return io::FormatDouble(value);
}

}  // namespace

std::int64_t ParseInteger(const std::string& flag, const std::string& text, std::int64_t min,
                          std::int64_t max, const std::string& what) {
  const std::string_view item = io::Trim(text);
  std::int64_t value = 0;
  const auto [end, error] = std::from_chars(item.data(), item.data() + item.size(), value);
  if (item.empty() || error != std::errc() || end != item.data() + item.size() || value < min ||
      value > max) {
    throw InputError(flag, 0,
                     "must be a whole number from " + std::to_string(min) + " to " +
                         std::to_string(max) + ", got '" + text + "'",
                     "give " + what + " in that range");
  }
  return value;
}

int ParseInt(const std::string& flag, const std::string& text, int min, int max,
             const std::string& what) {
  return static_cast<int>(ParseInteger(flag, text, min, max, what));
}

int ParseThreads(const std::string& flag, const std::string& text) {
  return ParseInt(flag, text, 0, kMaxThreads, "a thread count (0 = every core)");
}

int CheckThreads(const std::string& flag, int threads) {
  std::string why;
  if (!ThreadCountValid(threads, flag, &why)) throw OptionsError(why);
  return threads;
}

std::uint64_t ParseSeed(const std::string& flag, const std::string& text) {
  const std::string_view item = io::Trim(text);
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(item.data(), item.data() + item.size(), value);
  if (item.empty() || item.front() == '-' || error != std::errc() ||
      end != item.data() + item.size()) {
    throw InputError(flag, 0,
                     "must be a whole number from 0 to " +
                         std::to_string(std::numeric_limits<std::uint64_t>::max()) + ", got '" +
                         text + "'",
                     "give a seed in that range, e.g. " + flag + " 1");
  }
  return value;
}

void CheckNoiseLevel(const std::string& flag, double mm, double deg) {
  if (!(mm >= 0.0 && mm <= kMaxSigmaMm) || !(deg >= 0.0 && deg <= kMaxSigmaDeg)) {
    throw InputError(
        flag, 0,
        "noise levels must be 0 to " + Number(kMaxSigmaMm) + " mm and 0 to " +
            Number(kMaxSigmaDeg) + " deg per axis, got " + Number(mm) + " mm / " + Number(deg) +
            " deg",
        "give the standard deviation of one axis in mm and degrees, e.g. " + flag +
            (flag == "--robot-sigma" || flag == "--camera-sigma" ? " 0.5,0.1" : " 0.5/0.1"));
  }
}

}  // namespace hecal::cli
