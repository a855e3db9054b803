#include "cli.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <exception>
#include <sstream>
#include <string_view>

#include "field_flags.h"
#include "hecal/hecal.h"
#include "library_logs.h"

namespace hecal::cli {
namespace {

constexpr Registrar kRegistrars[] = {
    &RegisterPosesCommand,     &RegisterImportCommand,   &RegisterDetectCommand,
    &RegisterCalibrateCommand, &RegisterPivotCommand,    &RegisterPlanCommand,
    &RegisterReportCommand,    &RegisterPoseCommand,     &RegisterSimulateCommand,
    &RegisterBenchCommand,     &RegisterContourCommand,
};

// `hecal COMMAND --help` lists the flags most runs need, the ones below; `--help-all` lists every
// flag, the rest under "More options". docs/cli.md explains each. A command not listed here shows
// every flag in both (cli_docs_test holds every --help to 40 lines: list a longer one's common
// flags here).
struct CommonFlags {
  std::string_view command;
  std::string_view flags;  // space-separated long names
};
constexpr CommonFlags kCommonFlags[] = {
    {"calibrate",
     "--robot --camera --images --target --intrinsics --setup --method --output --report --units "
     "--degrees --euler --robot-inverse --camera-inverse --robot-sigma --camera-sigma --streams"},
    {"detect", "--images --target --intrinsics --output --report"},
    {"import", "--format --robot --camera --units --setup"},
    {"poses convert",
     "--input --output --to --units --degrees --invert --input-units --input-degrees --euler"},
    {"report", "--robot --images --output"},
    {"pose", "--points --image-points --focal --principal-point --intrinsics --method --output"},
    {"simulate",
     "--setup --stations --trials --sigma --method --noise --seed --output --summary --report "
     "--streams"},
    {"bench", "--stations --method --json"},
    {"contour pose", "--shape --z0 --focal --json"},
    {"contour study", "--motion --from --to --steps --output --report"},
    {"contour track", "--images --init --focal --z0 --principal-point --output"},
    {"contour render", "--output --to --focal --z0 --size --frames"},
};
constexpr std::string_view kMoreOptions = "More options";

bool IsCommon(std::string_view flags, const std::string& name) {
  std::istringstream words{std::string(flags)};
  for (std::string word; words >> word;)
    if (word == name) return true;
  return false;
}

// Hides the less common flags of every command (or, with `all`, groups them under "More options")
// and ends every help with where the rest is.
void LayOutHelp(CLI::App& app, const std::string& command, bool all) {
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
    LayOutHelp(*sub, command.empty() ? sub->get_name() : command + " " + sub->get_name(), all);
  const auto* common = std::find_if(std::begin(kCommonFlags), std::end(kCommonFlags),
                                    [&](const CommonFlags& c) { return c.command == command; });
  std::string last;
  if (common != std::end(kCommonFlags)) {
    for (CLI::Option* option : app.get_options()) {
      const std::string name = option->get_name();
      if (option->get_positional() || name == "--help" || IsCommon(common->flags, name)) continue;
      option->group(all ? std::string(kMoreOptions) : std::string());
    }
    last =
        all ? "Every flag explained: docs/cli.md"
            : "More flags: `hecal " + command + " --help-all`; every flag explained: docs/cli.md";
  } else if (!app.get_subcommands([](CLI::App*) { return true; }).empty()) {
    last = "A command's flags: `hecal " +
           (command.empty() ? std::string("COMMAND") : command + " COMMAND") +
           " --help`; every flag explained: docs/cli.md";
  } else {
    last = "Every flag explained: docs/cli.md";
  }
  const std::string footer = app.get_footer();
  app.footer(footer.empty() ? last : footer + "\n" + last);
}

}  // namespace

int RunHecal(const std::vector<std::string>& argv, std::ostream& out, std::ostream& err) {
  SilenceLibraryLogs();
  const Io io{out, err};
  CLI::App app{"hecal — hand–eye calibration with honest uncertainty", "hecal"};
  app.set_version_flag("--version", std::string(hecal::kVersion));
  app.require_subcommand(1);
  for (Registrar registrar : kRegistrars) registrar(app, io);

  // CLI11 wants the arguments without the program name, in reverse order. `--help-all` is
  // `--help` with every flag shown.
  std::vector<std::string> args(argv.rbegin(), argv.rend());
  if (!args.empty()) args.pop_back();
  const auto help_all = std::find(args.begin(), args.end(), "--help-all");
  if (help_all != args.end()) *help_all = "--help";
  LayOutHelp(app, "", help_all != args.end());
  try {
    app.parse(args);
    return 0;
  } catch (const CLI::Success& e) {  // --help, --version
    return app.exit(e, out, err);
  } catch (const CLI::ParseError& e) {
    err << "hecal: " << e.what() << " (fix: see `hecal --help` and the command's --help)\n";
    return 2;
  } catch (const InputError& e) {  // the library names options fields; the user typed flags
    err << "hecal: " << WithFlag(e).what() << "\n";
    return 2;
  } catch (const DegenerateError& e) {
    err << "hecal: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    err << "hecal: internal error: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace hecal::cli
