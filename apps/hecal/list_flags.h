// Flags that name things: one of a set of choices (--setup eye-in-hand, --units mm), comma-
// separated lists of them (simulate's --noise-on robot,camera) and of methods (simulate's and
// bench's --method park-martin,ml | all), and the one reading of a noise level (every sigma flag).
// Every parser throws hecal::InputError naming the flag and the offending item; numbers and their
// lists are bounds.h's.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "hecal/hecal.h"

namespace hecal::cli {

// Splits at commas and trims spaces; an empty list or an empty item is an InputError.
std::vector<std::string> SplitList(const std::string& flag, const std::string& text);

// One choice: `parse(text)` (a std::optional of the value, empty for an unknown name), or an
// InputError "unknown <what> '<text>'" whose fix is "use <choices>". The text is taken as given.
template <class Parse>
auto ParseChoice(const std::string& flag, const std::string& text, Parse parse,
                 const std::string& what, const std::string& choices) {
  auto value = parse(text);
  if (!value) throw InputError(flag, 0, "unknown " + what + " '" + text + "'", "use " + choices);
  return *value;
}

// A comma-separated list of choices: SplitList, then ParseChoice on every item.
template <class Parse>
auto ParseChoiceList(const std::string& flag, const std::string& text, Parse parse,
                     const std::string& what, const std::string& choices) {
  std::vector<decltype(ParseChoice(flag, text, parse, what, choices))> values;
  for (const std::string& item : SplitList(flag, text)) {
    values.push_back(ParseChoice(flag, item, parse, what, choices));
  }
  return values;
}

// Method names (docs/cli.md) or "all" (every method in estimation::AllMethods() order).
std::vector<estimation::Method> ParseMethodList(const std::string& flag, const std::string& text);

// --method of `hecal simulate` and `hecal bench`: a ParseMethodList flag, default all.
CLI::Option* AddMethodListFlag(CLI::App& command, std::vector<estimation::Method>& methods);

// Every method name, comma separated, for error messages and --help.
std::string MethodNames();

// A noise level per axis: two finite numbers "MM<separator>DEG" (calibrate's --robot-sigma
// 0.5,0.1; simulate's and bench's --sigma 0.5/0.1), or with `single` also "N" for N mm and N
// degrees (the thesis' "n mm / n°"). The range is the options' IsValid (estimation/pose_sigma.h).
study::NoiseLevel ParseNoiseLevel(const std::string& flag, const std::string& text, char separator,
                                  bool single);

// A comma-separated list of noise levels "N" or "MM/DEG" (simulate's --sigma 0,0.3,1,0.2/0.05).
std::vector<study::NoiseLevel> ParseNoiseLevels(const std::string& flag, const std::string& text);

}  // namespace hecal::cli
