// docs/cli.md against `hecal --help-all`: every subcommand the help lists (recursively, through
// the "Subcommands:" sections) has a section "## `hecal <command>`" in docs/cli.md, every flag its
// --help-all lists appears in that section as `--flag`, and every flag the section's table lists
// exists in the --help-all. So the reference cannot fall behind the command line. And `--help`
// of the top level and of every command fits a screen: at most 40 lines, the last pointing to
// docs/cli.md, its flags a subset of --help-all's.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli_test_util.h"

namespace hecal::cli {
namespace {

using cli_test::Hecal;

std::string ReadFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

struct Help {
  std::vector<std::string> subcommands;
  std::set<std::string> flags;  // long names with their dashes, without --help
};

// CLI11's help: option lines start with two spaces and the option names ("-h,--help",
// "--robot TEXT REQUIRED"); subcommand lines follow "Subcommands:" as "  name   description".
Help ParseHelp(const std::string& text) {
  Help help;
  static const std::regex kOption(R"(^  (?:-\w,)?(--[a-z0-9][a-z0-9-]*))");
  static const std::regex kSubcommand(R"(^  ([a-z][a-z0-9-]*)  )");
  std::istringstream lines(text);
  std::string line;
  bool in_subcommands = false;
  while (std::getline(lines, line)) {
    if (line.rfind("Subcommands:", 0) == 0) {
      in_subcommands = true;
      continue;
    }
    if (line.empty() || line[0] != ' ') in_subcommands = false;
    std::smatch match;
    if (in_subcommands && std::regex_search(line, match, kSubcommand)) {
      help.subcommands.push_back(match[1]);
    } else if (!in_subcommands && std::regex_search(line, match, kOption) && match[1] != "--help") {
      help.flags.insert(match[1]);
    }
  }
  return help;
}

// The text of "## `hecal <command>`" up to the next "## " heading; empty when absent.
std::string Section(const std::string& doc, const std::string& command) {
  const std::string heading = "\n## `hecal " + command + "`\n";
  const size_t begin = doc.find(heading);
  if (begin == std::string::npos) return "";
  const size_t end = doc.find("\n## ", begin + heading.size());
  return doc.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
}

// `hecal <command> <help_flag>`.
cli_test::Outcome RunHelp(const std::string& command, const std::string& help_flag) {
  std::vector<std::string> args;
  std::istringstream words(command);
  for (std::string word; words >> word;) args.push_back(word);
  args.push_back(help_flag);
  return Hecal(args);
}

// Every command ("" is the top level) and every leaf command, by walking the help from
// `hecal --help` down.
void CollectCommands(const std::string& command, std::vector<std::string>* leaves,
                     std::vector<std::string>* all) {
  const cli_test::Outcome help = RunHelp(command, "--help");
  ASSERT_EQ(help.code, 0) << command << ": " << help.err;
  all->push_back(command);
  const Help parsed = ParseHelp(help.out);
  if (parsed.subcommands.empty()) {
    leaves->push_back(command);
    return;
  }
  for (const std::string& sub : parsed.subcommands)
    CollectCommands(command.empty() ? sub : command + " " + sub, leaves, all);
}

TEST(CliDocs, EverySubcommandAndFlagIsInDocsCliMd) {
  const std::string doc = ReadFile(std::string(HECAL_SOURCE_DIR) + "/docs/cli.md");
  ASSERT_FALSE(doc.empty()) << "docs/cli.md is missing";
  std::vector<std::string> leaves, all;
  CollectCommands("", &leaves, &all);
  // poses convert, import, detect, calibrate, pose, simulate, bench, contour pose/study/track/
  // render: the walk must have found the command table, not an empty help.
  ASSERT_GE(leaves.size(), 11u);
  static const std::regex kTableFlag(R"(\n\| `(--[a-z0-9][a-z0-9-]*)`(?:, `(--[a-z0-9-]+)`)?)");
  for (const std::string& command : leaves) {
    SCOPED_TRACE("hecal " + command);
    const std::string section = Section(doc, command);
    ASSERT_FALSE(section.empty()) << "docs/cli.md has no section \"## `hecal " << command << "`\"";
    const Help help = ParseHelp(RunHelp(command, "--help-all").out);
    EXPECT_FALSE(help.flags.empty());
    for (const std::string& flag : help.flags) {
      EXPECT_NE(section.find("`" + flag + "`"), std::string::npos)
          << flag << " is missing from docs/cli.md";
    }
    for (std::sregex_iterator it(section.begin(), section.end(), kTableFlag), end; it != end;
         ++it) {
      for (size_t group = 1; group < it->size(); ++group) {
        if (!(*it)[group].matched) continue;
        EXPECT_TRUE(help.flags.contains((*it)[group]))
            << (*it)[group] << " is in docs/cli.md but not in --help";
      }
    }
  }
}

TEST(CliDocs, EveryHelpFitsAScreenAndEndsPointingToDocsCliMd) {
  std::vector<std::string> leaves, all;
  CollectCommands("", &leaves, &all);
  ASSERT_GE(all.size(), 14u);  // the top level, poses, contour and at least 11 leaves
  for (const std::string& command : all) {
    SCOPED_TRACE("hecal " + command + " --help");
    const cli_test::Outcome help = RunHelp(command, "--help");
    ASSERT_EQ(help.code, 0) << help.err;
    EXPECT_LE(std::count(help.out.begin(), help.out.end(), '\n'), 40) << help.out;
    std::string text = help.out;
    while (!text.empty() && text.back() == '\n') text.pop_back();
    const std::string last = text.substr(text.rfind('\n') + 1);
    EXPECT_NE(last.find("docs/cli.md"), std::string::npos) << last;
    const std::set<std::string> every = ParseHelp(RunHelp(command, "--help-all").out).flags;
    for (const std::string& flag : ParseHelp(help.out).flags)
      EXPECT_TRUE(every.contains(flag)) << flag << " is in --help but not in --help-all";
  }
}

TEST(CliDocs, HelpParserReadsCli11Layout) {
  const Help help = ParseHelp(
      "Usage: hecal x [OPTIONS]\n\nOptions:\n  -h,--help                   Print this help\n"
      "  --robot TEXT REQUIRED       Robot poses\n  --threads TEXT=0            Threads\n"
      "\nSubcommands:\n  convert                     Convert a pose table\n\n"
      "Methods:\n  linear: the first method --not-a-flag\n");
  EXPECT_EQ(help.flags, (std::set<std::string>{"--robot", "--threads"}));
  EXPECT_EQ(help.subcommands, std::vector<std::string>{"convert"});
}

}  // namespace
}  // namespace hecal::cli
