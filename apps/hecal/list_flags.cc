#include "list_flags.h"

#include <algorithm>
#include <cmath>

#include "hecal/hecal.h"

namespace hecal::cli {

std::vector<std::string> SplitList(const std::string& flag, const std::string& text) {
  std::vector<std::string> items;
  size_t start = 0;
  while (true) {
    const size_t comma = text.find(',', start);
    const std::string item(io::Trim(std::string_view(text).substr(
        start, comma == std::string::npos ? std::string::npos : comma - start)));
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

CLI::Option* AddMethodListFlag(CLI::App& command, std::vector<estimation::Method>& methods) {
  return command
      .add_option_function<std::string>(
          "--method",
          [&methods](const std::string& text) { methods = ParseMethodList("--method", text); },
          "Method name(s), comma separated, or all")
      ->default_str("all");
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
      const std::vector<estimation::Method> all = study::EveryMethod();
      methods.insert(methods.end(), all.begin(), all.end());
      continue;
    }
    methods.push_back(ParseChoice(flag, item, estimation::ParseMethod, "method",
                                  "all or one or more of " + MethodNames()));
  }
  // Keep the first occurrence of each method.
  std::vector<estimation::Method> unique;
  for (estimation::Method m : methods) {
    if (std::find(unique.begin(), unique.end(), m) == unique.end()) unique.push_back(m);
  }
  return unique;
}

study::NoiseLevel ParseNoiseLevel(const std::string& flag, const std::string& text, char separator,
                                  bool single) {
  const size_t split = text.find(separator);
  const bool two = split != std::string::npos;
  double values[2] = {0.0, 0.0};
  bool ok = two || single;
  const std::string parts[2] = {text.substr(0, split), two ? text.substr(split + 1) : ""};
  for (int k = 0; ok && k < (two ? 2 : 1); ++k) {
    ok = io::ParseDouble(io::Trim(parts[k]), &values[k]) && std::isfinite(values[k]);
  }
  if (!ok) {
    const std::string pair = std::string("MM") + separator + "DEG";
    throw InputError(
        flag, 0,
        "expected two numbers " + pair + (single ? " or one number N" : "") + ", got '" + text +
            "'",
        "write e.g. " + flag + " 0.5" + separator + "0.1 for 0.5 mm and 0.1 degree per axis");
  }
  return {values[0], two ? values[1] : values[0]};
}

std::vector<study::NoiseLevel> ParseNoiseLevels(const std::string& flag, const std::string& text) {
  std::vector<study::NoiseLevel> levels;
  for (const std::string& item : SplitList(flag, text)) {
    levels.push_back(ParseNoiseLevel(flag, item, '/', /*single=*/true));
  }
  return levels;
}

}  // namespace hecal::cli
