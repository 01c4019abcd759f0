// The documentation's promises that a test can keep: every short command of README.md's
// "A five-minute tour" runs with exit code 0 (commands marked "# long" are skipped; outputs go
// to a temporary directory instead of out/), and every relative Markdown link of README.md and
// docs/ points to a file that exists.
#include "tests/cli/cli_support.hpp"
#include "forward/io/text_file.hpp"

#include <gtest/gtest.h>

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

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  for (auto p = s.find(from); p != std::string::npos; p = s.find(from, p + to.size())) s.replace(p, from.size(), to);
  return s;
}

}  // namespace

TEST(ReadmeTour, EveryShortCommandExitsWithZero) {
  const fs::path source(SPIFIT_SOURCE_DIR);
  const auto lines = tour_commands(spifit::io::read_text_file((source / "README.md").string()));
  const fs::path out = spifit::test::temp_path("readme_tour");
  fs::remove_all(out);
  fs::create_directories(out);
  const std::string exe = "build/cli/spifit ";
  const fs::path cwd = fs::current_path();
  fs::current_path(source);  // the tour's relative paths are from the repository root
  int run = 0, skipped = 0;
  for (const auto& line : lines) {
    if (line.rfind(exe, 0) != 0) continue;  // output lines (#   -> ...) and blank lines
    const auto hash = line.find(" #");
    const std::string comment = hash == std::string::npos ? "" : line.substr(hash);
    if (comment.find("long") != std::string::npos) {
      ++skipped;
      continue;
    }
    std::string args = line.substr(exe.size(), hash == std::string::npos ? std::string::npos : hash - exe.size());
    std::string target = " ";  // (built by appends: GCC 12 warns falsely on " " + string&&)
    target += out.string();
    target += '/';
    args = replace_all(args, " out/", target);
    const auto r = spifit::test::run_spifit("-q " + args);
    EXPECT_EQ(r.code, 0) << "README tour: spifit " << args << "\n" << r.err;
    ++run;
  }
  fs::current_path(cwd);
  EXPECT_GE(run, 8) << "the tour's commands were not found in README.md";
  EXPECT_GE(skipped, 1) << "the tour marks its long commands with \"# long\"";
  fs::remove_all(out);
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
