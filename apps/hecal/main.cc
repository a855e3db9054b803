// hecal command-line entry point; all logic lives in the hecal_cli library (cli.h).
#include <iostream>
#include <string>
#include <vector>

#include "cli.h"

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv, argv + argc);
  return hecal::cli::RunHecal(args, std::cout, std::cerr);
}
