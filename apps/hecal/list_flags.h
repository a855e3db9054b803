// Comma-separated list flags shared by `hecal simulate` and `hecal bench` (e.g. --stations
// 10,20,50, --method park-martin,ml | all). Every parser throws hecal::InputError naming the flag
// and the offending item.
#pragma once

#include <string>
#include <vector>

#include "hecal/estimation/methods.h"

namespace hecal::cli {

// Splits at commas and trims spaces; an empty list or an empty item is an InputError.
std::vector<std::string> SplitList(const std::string& flag, const std::string& text);

// Integers in [minimum, maximum] (an item outside is an InputError naming the range).
std::vector<int> ParseIntList(const std::string& flag, const std::string& text, int minimum,
                              int maximum);

// Method names (docs/cli.md) or "all" (every method in estimation::AllMethods() order).
std::vector<estimation::Method> ParseMethodList(const std::string& flag, const std::string& text);

// Every method name, comma separated, for error messages and --help.
std::string MethodNames();

// A finite non-negative number.
double ParseNonNegative(const std::string& flag, const std::string& text);

// A noise level: "n" (n mm and n degrees per component, the thesis' "n mm / n°") or "MM/DEG".
struct SigmaLevel {
  double mm = 0.0;
  double deg = 0.0;
};
SigmaLevel ParseSigmaLevel(const std::string& flag, const std::string& text);

}  // namespace hecal::cli
