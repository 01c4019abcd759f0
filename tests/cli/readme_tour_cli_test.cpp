// The documentation's promises that a test can keep: every short command of README.md's
// "A five-minute tour" and of every ```sh block of docs/guide/ runs with exit code 0, or with the
// code its comment names ("# exits 1: ..."; commands whose comment says "long" are skipped;
// outputs go to a temporary directory instead of out/, one per page, the commands of a page in
// order), and every relative Markdown link of README.md and docs/ points to a file that exists.
#include "tests/cli/cli_support.hpp"
#include "forward/io/text_file.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

// The lines of the first ```sh block after the heading "## A five-minute tour".
std::vector<std::string> tour_commands(const std::string& readme) {
  std::vector<std::string> lines;
  const auto heading = readme.find("## A five-minute tour");
  if (heading == std::string::npos) return lines;
  const auto open = readme.find("```sh\n", heading);
  if (open == std::string::npos) return lines;
  const auto close = readme.find("\n```", open + 6);
  std::istringstream in(readme.substr(open + 6, close - open - 6));
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// The lines of every ```sh block of a page.
std::vector<std::string> sh_block_lines(const std::string& page) {
  std::vector<std::string> lines;
  for (auto open = page.find("```sh\n"); open != std::string::npos; open = page.find("```sh\n", open + 6)) {
    const auto close = page.find("\n```", open + 6);
    std::istringstream in(page.substr(open + 6, close - open - 6));
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    open = close;
  }
  return lines;
}

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  for (auto p = s.find(from); p != std::string::npos; p = s.find(from, p + to.size())) s.replace(p, from.size(), to);
  return s;
}

struct Ran {
  int run = 0, skipped = 0;
};

// Runs the spifit commands among lines ("build/cli/spifit ARGS" or "spifit ARGS", a comment
// after " #") from the repository root, out/ replaced by the directory out; where names the page.
Ran run_commands(const std::vector<std::string>& lines, const fs::path& out, const std::string& where) {
  Ran n;
  const fs::path source(SPIFIT_SOURCE_DIR);
  fs::remove_all(out);
  fs::create_directories(out);
  const fs::path cwd = fs::current_path();
  fs::current_path(source);  // the pages' relative paths are from the repository root
  for (const auto& line : lines) {
    std::string args;
    for (const std::string exe : {"build/cli/spifit ", "spifit "})
      if (args.empty() && line.rfind(exe, 0) == 0) args = line.substr(exe.size());
    if (args.empty()) continue;  // output lines ("# ..."), scripts and blank lines
    const auto hash = args.find(" #");
    if (hash != std::string::npos && args.find("long", hash) != std::string::npos) {
      ++n.skipped;
      continue;
    }
    // "# exits N": the code the page promises (a fit that is not usable exits 1).
    int expected = 0;
    if (hash != std::string::npos) {
      const auto exits = args.find("exits ", hash);
      if (exits != std::string::npos) expected = std::atoi(args.c_str() + exits + 6);
    }
    args = args.substr(0, hash);
    std::string target = " ";  // (built by appends: GCC 12 warns falsely on " " + string&&)
    target += out.string();
    target += '/';
    args = replace_all(args, " out/", target);
    const auto r = spifit::test::run_spifit("-q " + args);
    EXPECT_EQ(r.code, expected) << where << ": spifit " << args << "\n" << r.err;
    ++n.run;
  }
  fs::current_path(cwd);
  fs::remove_all(out);
  return n;
}

}  // namespace

TEST(ReadmeTour, EveryShortCommandExitsWithZero) {
  const fs::path source(SPIFIT_SOURCE_DIR);
  const auto lines = tour_commands(spifit::io::read_text_file((source / "README.md").string()));
  const Ran n = run_commands(lines, spifit::test::temp_path("readme_tour"), "README tour");
  EXPECT_GE(n.run, 8) << "the tour's commands were not found in README.md";
  EXPECT_GE(n.skipped, 1) << "the tour marks its long commands with \"# long\"";
}

TEST(GuideCommands, EveryShortCommandExitsWithZero) {
  const fs::path source(SPIFIT_SOURCE_DIR);
  std::vector<fs::path> pages;
  for (const auto& e : fs::directory_iterator(source / "docs" / "guide"))
    if (e.path().extension() == ".md") pages.push_back(e.path());
  std::sort(pages.begin(), pages.end());
  int run = 0, skipped = 0;
  for (const auto& page : pages) {
    const auto lines = sh_block_lines(spifit::io::read_text_file(page.string()));
    const Ran n = run_commands(lines, spifit::test::temp_path("guide_" + page.stem().string()), "docs/guide/" + page.filename().string());
    run += n.run;
    skipped += n.skipped;
  }
  EXPECT_GE(run, 12) << "the guide's commands were not found";
  EXPECT_GE(skipped, 5);
}

TEST(DocsLinks, EveryRelativeLinkPointsToAFile) {
  const fs::path source(SPIFIT_SOURCE_DIR);
  std::vector<fs::path> files{source / "README.md", source / "experiments" / "README.md"};
  for (const auto& e : fs::recursive_directory_iterator(source / "docs"))
    if (e.path().extension() == ".md") files.push_back(e.path());
  const std::regex link(R"(\]\(([^)#\s]+)(#[^)\s]*)?\))");
  int links = 0;
  for (const auto& file : files) {
    const std::string text = spifit::io::read_text_file(file.string());
    for (std::sregex_iterator m(text.begin(), text.end(), link), end; m != end; ++m) {
      const std::string target = (*m)[1].str();
      if (target.find("://") != std::string::npos || target.rfind("mailto:", 0) == 0) continue;
      ++links;
      EXPECT_TRUE(fs::exists(file.parent_path() / target)) << file.lexically_relative(source).string() << ": link to " << target;
    }
  }
  EXPECT_GT(links, 50);
}
