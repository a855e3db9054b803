// Internal: "did you mean ...?" suggestions for misspelt keys and names in hecal's input files.
#pragma once

#include <span>
#include <string>
#include <string_view>

namespace hecal::io::internal {

// Levenshtein distance (insertions, deletions, substitutions) between two strings.
size_t EditDistance(std::string_view a, std::string_view b);

// The candidate nearest to `name` by edit distance ignoring letter case, or "" when even the
// nearest needs more than max(2, |name| / 4) edits (a different word, not a slip). Ties go to the
// earlier candidate.
std::string ClosestName(std::string_view name, std::span<const std::string_view> candidates);

// " (did you mean 'X'?)" for ClosestName's answer, "" when it has none.
std::string DidYouMean(std::string_view name, std::span<const std::string_view> candidates);

}  // namespace hecal::io::internal
