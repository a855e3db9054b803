// Test support for the io tests: the root of the source tree, under which live the data sets
// (data/) and the hand-made fixtures (src/io/testdata/) that several readers are tested on.
#pragma once

#include <string>

namespace hecal::io::test_util {

inline const std::string kSource = std::string(HECAL_SOURCE_DIR);

}  // namespace hecal::io::test_util
