// Choices shared by several commands: see choice_flags.h.
#include "choice_flags.h"

namespace hecal::cli {

CLI::Option* AddSetupFlag(CLI::App& command, std::optional<handeye::Setup>& setup,
                          SetupChoices choices, const std::string& help) {
  const bool with_auto = choices == SetupChoices::kGivenOrAuto;
  return AddChoice<std::optional<handeye::Setup>>(
      command, "--setup", setup,
      [with_auto](std::string_view text) -> std::optional<std::optional<handeye::Setup>> {
        if (with_auto && text == "auto") return std::optional<handeye::Setup>();
        const std::optional<handeye::Setup> given = handeye::ParseSetup(text);
        if (!given) return std::nullopt;
        return given;
      },
      "setup",
      with_auto ? "use eye-in-hand (camera on the robot), eye-to-hand (camera fixed) or auto (the "
                  "one the data fit)"
                : "use eye-in-hand (camera on the robot) or eye-to-hand (camera fixed)",
      help);
}

CLI::Option* AddEulerFlag(CLI::App& command, const std::string& flag,
                          std::optional<EulerSequence>& sequence, const std::string& help) {
  return AddChoice<EulerSequence>(command, flag, sequence, EulerSequence::Parse, "Euler sequence",
                                  "use three axis letters, lowercase = extrinsic, uppercase = "
                                  "intrinsic (e.g. xyz, ZYX, ZXZ)",
                                  help);
}

}  // namespace hecal::cli
