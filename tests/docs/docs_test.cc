// The repository explains itself: every relative link in docs/*.md and README.md resolves to a
// file of the repository (and a `#anchor` to a heading of the target page, by GitHub's slug
// rule), and no source, test, script or page cites a document outside the repository — the
// design and specification notes the project started from, issue numbers or the source
// documents by their numbers — since a reader who clones the repository cannot open them.
// Citations go to papers and to docs/ pages instead (docs/README.md lists them).
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
const fs::path kRoot = HECAL_SOURCE_DIR;

std::string ReadFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Markdown text without fenced code blocks and inline code spans (links there are examples).
std::string WithoutCode(const std::string& text) {
  std::string out;
  std::istringstream lines(text);
  bool fenced = false;
  for (std::string line; std::getline(lines, line);) {
    const size_t first = line.find_first_not_of(' ');
    if (first != std::string::npos && line.compare(first, 3, "```") == 0) {
      fenced = !fenced;
      out += "\n";
      continue;
    }
    if (fenced) {
      out += "\n";
      continue;
    }
    bool in_span = false;
    for (char c : line) {
      if (c == '`')
        in_span = !in_span;
      else if (!in_span)
        out += c;
    }
    out += "\n";
  }
  return out;
}

// GitHub's heading anchor: lowercase; letters, digits, '-' and '_' kept (non-ASCII letters too),
// spaces become '-', other punctuation (ASCII, and the typographic marks used in headings) goes.
std::string Slug(const std::string& heading) {
  static const std::vector<std::string> kDropped = {"–", "—", "·", "×", "→", "←", "’",
                                                    "“", "”", "…", "²", "⁻", "¹"};
  std::string slug;
  for (size_t i = 0; i < heading.size();) {
    const unsigned char c = static_cast<unsigned char>(heading[i]);
    if (c >= 0x80) {
      size_t length = (c >= 0xF0) ? 4 : (c >= 0xE0) ? 3 : 2;
      const std::string glyph = heading.substr(i, length);
      if (std::find(kDropped.begin(), kDropped.end(), glyph) == kDropped.end()) slug += glyph;
      i += length;
      continue;
    }
    if (std::isalnum(c) || c == '-' || c == '_')
      slug += static_cast<char>(std::tolower(c));
    else if (c == ' ')
      slug += '-';
    ++i;
  }
  return slug;
}

std::set<std::string> Anchors(const std::string& markdown) {
  std::set<std::string> anchors;
  std::istringstream lines(markdown);
  bool fenced = false;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("```", 0) == 0) fenced = !fenced;
    if (fenced || line.empty() || line[0] != '#') continue;
    const size_t text = line.find_first_not_of('#');
    if (text == std::string::npos || line[text] != ' ') continue;
    std::string slug = Slug(line.substr(text + 1));
    // Repeated headings get -1, -2, … as on GitHub.
    std::string unique = slug;
    for (int k = 1; anchors.contains(unique); ++k) unique = slug + "-" + std::to_string(k);
    anchors.insert(unique);
  }
  return anchors;
}

struct Link {
  std::string target;
  int line = 0;
};

// Targets of [text](target) and ![alt](target).
std::vector<Link> Links(const std::string& markdown) {
  std::vector<Link> links;
  const std::string text = WithoutCode(markdown);
  int line = 1;
  for (size_t i = 0; i + 1 < text.size(); ++i) {
    if (text[i] == '\n') ++line;
    if (text[i] != ']' || text[i + 1] != '(') continue;
    const size_t end = text.find(')', i + 2);
    if (end == std::string::npos) continue;
    std::string target = text.substr(i + 2, end - i - 2);
    if (const size_t space = target.find(' '); space != std::string::npos)
      target = target.substr(0, space);  // [text](target "title")
    links.push_back({target, line});
  }
  return links;
}

std::vector<fs::path> Pages() {
  std::vector<fs::path> pages = {kRoot / "README.md"};
  for (const fs::directory_entry& entry : fs::directory_iterator(kRoot / "docs"))
    if (entry.path().extension() == ".md") pages.push_back(entry.path());
  std::sort(pages.begin(), pages.end());
  return pages;
}

TEST(Docs, SlugFollowsGitHub) {
  EXPECT_EQ(Slug("The image folder (`--images DIR`)"), "the-image-folder---images-dir");
  EXPECT_EQ(Slug("Accuracy: the thesis study"), "accuracy-the-thesis-study");
  EXPECT_EQ(Slug("`covariance.model_check`"), "covariancemodel_check");
  EXPECT_EQ(Slug("Target-free, globally optimal hand–eye calibration"),
            "target-free-globally-optimal-handeye-calibration");
}

TEST(Docs, EveryRelativeLinkResolves) {
  const std::vector<fs::path> pages = Pages();
  ASSERT_GE(pages.size(), 10u) << "docs/ pages not found under " << kRoot;
  int checked = 0;
  for (const fs::path& page : pages) {
    const std::string text = ReadFile(page);
    for (const Link& link : Links(text)) {
      const std::string& target = link.target;
      if (target.rfind("http://", 0) == 0 || target.rfind("https://", 0) == 0 ||
          target.rfind("mailto:", 0) == 0)
        continue;
      const std::string where =
          fs::relative(page, kRoot).string() + ":" + std::to_string(link.line) + ": " + target;
      const size_t hash = target.find('#');
      const std::string path = target.substr(0, hash);
      const fs::path file = path.empty() ? page : page.parent_path() / path;
      ++checked;
      ASSERT_TRUE(fs::exists(file)) << where << ": no such file";
      EXPECT_TRUE(
          fs::weakly_canonical(file).string().rfind(fs::weakly_canonical(kRoot).string(), 0) == 0)
          << where << ": outside the repository";
      if (hash == std::string::npos) continue;
      ASSERT_EQ(file.extension(), ".md") << where << ": an anchor into a non-page";
      const std::string anchor = target.substr(hash + 1);
      EXPECT_TRUE(Anchors(ReadFile(file)).contains(anchor)) << where << ": no such heading";
    }
  }
  EXPECT_GE(checked, 50);  // the pages do link to each other: the scan found them
}

// The words that cite documents outside the repository, found case-insensitively. The
// patterns are spelled so that this file does not match them itself.
std::vector<std::string> Citations(const std::string& content) {
  std::string text = content;
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  std::vector<std::string> found;
  for (const std::string& word : {std::string("design") + ".md", std::string("spec") + ".md",
                                  std::string("f") + "ounding", std::string("seed") + " paper",
                                  std::string("seed") + " document", std::string("..") + "/shared"})
    if (text.find(word) != std::string::npos) found.push_back(word);
  // "issue N" and "seed 00N"
  for (const std::string& prefix : {std::string("issue "), std::string("seed 00")}) {
    for (size_t at = text.find(prefix); at != std::string::npos; at = text.find(prefix, at + 1)) {
      const size_t next = at + prefix.size();
      if (next < text.size() && std::isdigit(static_cast<unsigned char>(text[next])))
        found.push_back(text.substr(at, prefix.size() + 1));
    }
  }
  return found;
}

TEST(Docs, CitationFinderFindsEachForm) {
  EXPECT_EQ(Citations(std::string("see Iss") + "ue 3").size(), 1u);
  EXPECT_EQ(Citations(std::string("as in seed 0") + "04's method").size(), 1u);
  EXPECT_EQ(Citations(std::string("(DESIGN") + ".md §2)").size(), 1u);
  EXPECT_EQ(Citations(std::string("the random seed 1, issues with tabs, --seed 0") + "04").size(),
            1u);
  EXPECT_TRUE(Citations("the seed is fixed; see docs/conventions.md").empty());
}

TEST(Docs, NothingCitesDocumentsOutsideTheRepository) {
  const std::vector<std::string> roots = {"src",   "include", "apps",  "docs",  "bench", "fuzz",
                                          "tests", "scripts", "tools", "cmake", ".ci"};
  std::vector<fs::path> files = {kRoot / "README.md", kRoot / "CMakeLists.txt"};
  for (const std::string& root : roots) {
    if (!fs::exists(kRoot / root)) continue;
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(kRoot / root))
      if (entry.is_regular_file() && entry.file_size() < (1u << 20)) files.push_back(entry.path());
  }
  ASSERT_GE(files.size(), 200u);
  for (const fs::path& file : files) {
    const std::string content = ReadFile(file);
    if (content.find('\0') != std::string::npos) continue;  // binary (fuzz corpora, images)
    for (const std::string& citation : Citations(content))
      ADD_FAILURE() << fs::relative(file, kRoot).string() << " cites \"" << citation
                    << "\": cite the paper or the docs/ page instead";
  }
}

}  // namespace
