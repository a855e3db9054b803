// Resource bounds every job shares (docs/cli.md, "Bounds"): a value above them is refused by the
// options' IsValid (core/options_check.h) before any work, so no option alone can ask for more
// than a workstation has.
#pragma once

namespace hecal {

// Worker threads of a parallel job; 0 means every core.
inline constexpr int kMaxThreads = 256;

}  // namespace hecal
