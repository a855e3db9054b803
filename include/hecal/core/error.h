// Errors a user can act on. Everything hecal rejects because of its input is reported with one of
// these; the CLI prints `what()` as one line on stderr and exits with code 2 (docs/cli.md).
//
//   InputError      — a file or an option is malformed: names the source, the line (0 when not
//                     line-bound), what is wrong and how to fix it.
//   DegenerateError — the data are well formed but do not determine the unknowns (parallel
//                     rotation axes, too few stations, ...): names what cannot be observed.
#pragma once

#include <stdexcept>
#include <string>

namespace hecal {

class InputError : public std::runtime_error {
 public:
  // `source` is a file name or the options field that holds the bad value, as
  // "Struct.field" (e.g. "CalibrateOptions.robust_loss"; the CLI shows the flag that sets it);
  // `line` is 1-based, 0 = whole source.
  InputError(std::string source, int line, std::string problem, std::string fix)
      : std::runtime_error(Format(source, line, problem, fix)),
        source_(std::move(source)),
        line_(line),
        problem_(std::move(problem)),
        fix_(std::move(fix)) {}

  const std::string& source() const { return source_; }
  int line() const { return line_; }
  const std::string& problem() const { return problem_; }
  const std::string& fix() const { return fix_; }

 private:
  static std::string Format(const std::string& source, int line, const std::string& problem,
                            const std::string& fix) {
    // Appends piece by piece: `":" + std::to_string(line)` trips GCC 12's -Wrestrict false
    // positive (GCC bug 105329) in every -O2 -Werror translation unit that includes this header.
    std::string message = source;
    if (line > 0) {
      message += ':';
      message += std::to_string(line);
    }
    message += ": ";
    message += problem;
    if (!fix.empty()) {
      message += " (fix: ";
      message += fix;
      message += ')';
    }
    return message;
  }

  std::string source_;
  int line_;
  std::string problem_;
  std::string fix_;
};

class DegenerateError : public std::runtime_error {
 public:
  // `unobservable` names what the data cannot determine, e.g. "translation along the common
  // rotation axis"; `fix` says what data would make it observable.
  DegenerateError(std::string unobservable, std::string fix)
      : std::runtime_error("degenerate data: cannot observe " + unobservable +
                           (fix.empty() ? std::string() : " (fix: " + fix + ")")),
        unobservable_(std::move(unobservable)) {}

  const std::string& unobservable() const { return unobservable_; }

 private:
  std::string unobservable_;
};

}  // namespace hecal
