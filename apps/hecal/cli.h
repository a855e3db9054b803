// The hecal command line: a table of subcommands, each in its own file with a testable Run*
// function (COLMAP-style). RunHecal parses argv, runs the chosen subcommand and maps failures to
// exit codes (docs/cli.md): 0 success, 2 bad input (InputError, DegenerateError, bad flags; one
// line on stderr), 1 internal error.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace hecal::cli {

// Where a command prints. Tests pass string streams.
struct Io {
  std::ostream& out;
  std::ostream& err;
};

// Every subcommand file provides one of these; it adds its CLI11 subcommand(s) to `app` with a
// callback that runs the command. Callbacks report bad input by throwing hecal::InputError.
using Registrar = void (*)(CLI::App& app, const Io& io);

// Registrars, one per subcommand file (keep in the order `hecal --help` lists them).
void RegisterPosesCommand(CLI::App& app, const Io& io);
void RegisterImportCommand(CLI::App& app, const Io& io);
void RegisterDetectCommand(CLI::App& app, const Io& io);
void RegisterCalibrateCommand(CLI::App& app, const Io& io);
void RegisterPivotCommand(CLI::App& app, const Io& io);
void RegisterReportCommand(CLI::App& app, const Io& io);
void RegisterPoseCommand(CLI::App& app, const Io& io);
void RegisterSimulateCommand(CLI::App& app, const Io& io);
void RegisterBenchCommand(CLI::App& app, const Io& io);
void RegisterContourCommand(CLI::App& app, const Io& io);
void RegisterPlanCommand(CLI::App& app, const Io& io);

// argv[0] is the program name, as in main().
int RunHecal(const std::vector<std::string>& argv, std::ostream& out, std::ostream& err);

}  // namespace hecal::cli
