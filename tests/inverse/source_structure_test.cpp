// The structure of the rooms above the forward model, read from the sources so that a change that
// breaks it fails here, naming the file:
//  * inverse/ has no include loop between its parts (a module, a .hpp with its .cpp, that includes
//    another, directly or through others, is never included back by it);
//  * inverse/ and reports/ know no scene kind: no dynamic_cast (to a scene result or anything
//    else) and no kind or family name in quotes; what they need of a kind comes through the scene
//    registry (SceneKind, Scene, SceneResult).
#include "forward/scenes/scene_registry.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

using Graph = std::map<std::string, std::set<std::string>>;

// Module "inverse/fit_file" -> the modules of the same folder its .hpp and .cpp include.
Graph module_includes(const std::string& folder) {
  const fs::path root(SPIFIT_SOURCE_DIR);
  Graph g;
  const std::regex include("#include \"(" + folder + "/[^\"]+)\\.hpp\"");
  for (const auto& entry : fs::recursive_directory_iterator(root / folder)) {
    const std::string ext = entry.path().extension().string();
    if (ext != ".hpp" && ext != ".cpp") continue;
    const std::string module = fs::relative(entry.path(), root).replace_extension().string();
    g[module];
    std::ifstream in(entry.path());
    std::stringstream text;
    text << in.rdbuf();
    const std::string s = text.str();
    for (std::sregex_iterator it(s.begin(), s.end(), include), end; it != end; ++it)
      if ((*it)[1] != module) g[module].insert((*it)[1]);
  }
  return g;
}

// A loop "a -> b -> a" if there is one, else empty (depth-first search with colours).
std::vector<std::string> find_loop(const Graph& g) {
  std::map<std::string, int> colour;  // 0 new, 1 on the path, 2 done
  std::vector<std::string> path, loop;
  std::function<bool(const std::string&)> visit = [&](const std::string& m) {
    colour[m] = 1;
    path.push_back(m);
    const auto found = g.find(m);
    if (found != g.end()) {
      for (const auto& n : found->second) {
        if (colour[n] == 1) {
          auto start = std::find(path.begin(), path.end(), n);
          loop.assign(start, path.end());
          loop.push_back(n);
          return true;
        }
        if (colour[n] == 0 && visit(n)) return true;
      }
    }
    path.pop_back();
    colour[m] = 2;
    return false;
  };
  for (const auto& [m, _] : g)
    if (colour[m] == 0 && visit(m)) return loop;
  return {};
}

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : " -> ") + x;
  return s;
}

// file: line for every line of the folder's sources that contains one of `needles`.
std::vector<std::string> lines_with(const std::string& folder, const std::vector<std::string>& needles) {
  const fs::path root(SPIFIT_SOURCE_DIR);
  std::vector<std::string> hits;
  for (const auto& entry : fs::recursive_directory_iterator(root / folder)) {
    const std::string ext = entry.path().extension().string();
    if (ext != ".hpp" && ext != ".cpp") continue;
    std::ifstream in(entry.path());
    std::string line;
    for (int n = 1; std::getline(in, line); ++n)
      for (const auto& needle : needles)
        if (line.find(needle) != std::string::npos) hits.push_back(fs::relative(entry.path(), root).string() + ":" + std::to_string(n) + ": " + needle);
  }
  return hits;
}

}  // namespace

TEST(IncludeStructure, InverseHasNoIncludeLoop) {
  const Graph g = module_includes("inverse");
  ASSERT_GT(g.size(), 30u);  // the folder was found and read
  EXPECT_EQ(joined(find_loop(g)), "");
}

// The checker finds a loop when there is one.
TEST(IncludeStructure, CheckerFindsALoop) {
  const Graph g{{"a", {"b"}}, {"b", {"c"}}, {"c", {"a"}}, {"d", {"a"}}};
  EXPECT_EQ(joined(find_loop(g)), "a -> b -> c -> a");
  EXPECT_EQ(joined(find_loop(Graph{{"a", {"b"}}, {"b", {}}})), "");
}

// The parts of inverse/ (its subfolders) include only downwards: no loop between folders either.
TEST(IncludeStructure, InverseFoldersHaveNoLoop) {
  Graph folders;
  auto folder_of = [](const std::string& module) {
    const std::size_t a = module.find('/'), b = module.find('/', a + 1);
    return b == std::string::npos ? module.substr(0, a) : module.substr(0, b);
  };
  for (const auto& [m, includes] : module_includes("inverse")) {
    folders[folder_of(m)];
    for (const auto& i : includes)
      if (folder_of(i) != folder_of(m)) folders[folder_of(m)].insert(folder_of(i));
  }
  EXPECT_EQ(folders.size(), 5u);  // runs, experiments, fit, uncertainty, sweeps
  EXPECT_EQ(joined(find_loop(folders)), "");
}

TEST(SceneKindKnowledge, InverseAndReportsNameNoKind) {
  std::vector<std::string> needles{"dynamic_cast"};
  for (const auto& k : spifit::scene::scene_kinds()) {
    needles.push_back("\"" + k.name + "\"");
    needles.push_back("\"" + k.family + "\"");
  }
  ASSERT_GT(needles.size(), 8u);  // the registry was read
  for (const char* folder : {"inverse", "reports"}) {
    std::string found;
    for (const auto& h : lines_with(folder, needles)) found += h + "\n";
    EXPECT_EQ(found, "") << folder;
  }
}
