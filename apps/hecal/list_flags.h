// Comma-separated list flags shared by `hecal simulate` and `hecal bench` (e.g. --method
// park-martin,ml | all), and the one reading of a noise level (every sigma flag). Every parser
// throws hecal::InputError naming the flag and the offending item; whole-number lists are bound
// typed (bounds.h, AddWholeNumberList).
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "hecal/estimation/methods.h"
#include "hecal/study/study.h"

namespace hecal::cli {

// Splits at commas and trims spaces; an empty list or an empty item is an InputError.
std::vector<std::string> SplitList(const std::string& flag, const std::string& text);

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

}  // namespace hecal::cli
