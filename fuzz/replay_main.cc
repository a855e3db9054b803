// Replays kept fuzzer inputs without libFuzzer: a main() for any fuzz/fuzz_<name>.cc that calls its
// LLVMFuzzerTestOneInput once per file of the folders (or files) named on the command line, in
// name order, so the unit tests (and the sanitized robustness run, scripts/test.sh) replay every
// seed of fuzz/corpus/<name>/ and every finding of tests/data/fuzz-regressions/<name>/ through the
// fuzzer's own property checks with any compiler. A violated property aborts, as under libFuzzer.
// README.md files are skipped; a missing folder counts nothing. Exit 1 when no input was replayed
// at all (a corpus moved or emptied), else 0; prints "<N> inputs replayed".
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace {

namespace fs = std::filesystem;

std::vector<fs::path> Inputs(const fs::path& root) {
  std::vector<fs::path> paths;
  if (fs::is_regular_file(root)) return {root};
  if (!fs::is_directory(root)) return paths;
  for (const fs::directory_entry& entry : fs::directory_iterator(root)) {
    if (entry.is_regular_file() && entry.path().filename() != "README.md") {
      paths.push_back(entry.path());
    }
  }
  std::sort(paths.begin(), paths.end());
  return paths;
}

}  // namespace

int main(int argc, char** argv) {
  int replayed = 0;
  for (int i = 1; i < argc; ++i) {
    for (const fs::path& path : Inputs(argv[i])) {
      std::ifstream in(path, std::ios::binary);
      const std::string bytes((std::istreambuf_iterator<char>(in)),
                              std::istreambuf_iterator<char>());
      std::printf("%s (%zu bytes)\n", path.c_str(), bytes.size());
      std::fflush(stdout);  // the input a crash happened on is the last line printed
      LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
      ++replayed;
    }
  }
  std::printf("%d inputs replayed\n", replayed);
  return replayed > 0 ? 0 : 1;
}
