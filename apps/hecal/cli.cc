#include "cli.h"

#include <CLI/CLI.hpp>
#include <exception>

#include "field_flags.h"
#include "hecal/hecal.h"
#include "library_logs.h"

namespace hecal::cli {
namespace {

constexpr Registrar kRegistrars[] = {
    &RegisterPosesCommand,     &RegisterImportCommand,   &RegisterDetectCommand,
    &RegisterCalibrateCommand, &RegisterPivotCommand,    &RegisterReportCommand,
    &RegisterPoseCommand,      &RegisterSimulateCommand, &RegisterBenchCommand,
    &RegisterContourCommand,
};

}  // namespace

int RunHecal(const std::vector<std::string>& argv, std::ostream& out, std::ostream& err) {
  SilenceLibraryLogs();
  const Io io{out, err};
  CLI::App app{"hecal — hand–eye calibration with honest uncertainty", "hecal"};
  app.set_version_flag("--version", std::string(hecal::kVersion));
  app.require_subcommand(1);
  for (Registrar registrar : kRegistrars) registrar(app, io);

  // CLI11 wants the arguments without the program name, in reverse order.
  std::vector<std::string> args(argv.rbegin(), argv.rend());
  if (!args.empty()) args.pop_back();
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
