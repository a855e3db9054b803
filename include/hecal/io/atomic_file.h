// Never a partial output file (DESIGN.md §4): write to a temporary name in the same directory,
// flush, then rename over the target. On failure the target is untouched and the temporary file
// removed; failures throw hecal::InputError naming the path (e.g. a missing directory).
#pragma once

#include <string>
#include <string_view>

namespace hecal::io {

void WriteFileAtomically(const std::string& path, std::string_view contents);

// Reads a whole file; throws InputError (path, "cannot read ...") when it cannot.
std::string ReadFile(const std::string& path);

}  // namespace hecal::io
