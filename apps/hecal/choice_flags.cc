// Choices shared by several commands: see choice_flags.h.
#include "choice_flags.h"

namespace hecal::cli {

CLI::Option* AddSetupOrAutoFlag(CLI::App& command, std::optional<handeye::Setup>& setup,
                                const std::string& help) {
  return AddChoice<std::optional<handeye::Setup>>(
      command, "--setup", setup,
      [](std::string_view text) -> std::optional<std::optional<handeye::Setup>> {
        if (text == "auto") return std::optional<handeye::Setup>();
        const std::optional<handeye::Setup> given = handeye::ParseSetup(text);
        if (!given) return std::nullopt;
        return given;
      },
      "setup",
      "eye-in-hand (camera on the robot), eye-to-hand (camera fixed) or auto (the one the data "
      "fit)",
      help);
}

CLI::Option* AddEulerFlag(CLI::App& command, const std::string& flag,
                          std::optional<EulerSequence>& sequence, const std::string& help) {
  return AddChoice<EulerSequence>(command, flag, sequence, EulerSequence::Parse, "Euler sequence",
                                  "three axis letters, lowercase = extrinsic, uppercase = "
                                  "intrinsic (e.g. xyz, ZYX, ZXZ)",
                                  help);
}

}  // namespace hecal::cli
