#include "forward/scenes/scene_registry.hpp"

#include "forward/io/toml_reader.hpp"
#include "forward/scenes/benchmark/shell_benchmark_kind.hpp"
#include "forward/scenes/cone/cone_kind.hpp"
#include "forward/scenes/forming/forming_kind.hpp"
#include "forward/scenes/material_point/material_point_kind.hpp"

#include <algorithm>
#include <stdexcept>

namespace spifit::scene {
namespace {

std::deque<SceneKind> all_kinds() {
  std::deque<SceneKind> k;
  auto add = [&k](std::vector<SceneKind> more) {
    for (auto& x : more) k.push_back(std::move(x));
  };
  // One line per kind (or family of kinds):
  add(material_point_kinds());
  add({shell_benchmark_kind()});
  add(forming_kinds());
  add({cone_kind()});
  return k;
}

std::deque<SceneKind>& registry() {
  static std::deque<SceneKind> kinds = all_kinds();
  return kinds;
}

}  // namespace

const std::deque<SceneKind>& scene_kinds() { return registry(); }

void register_scene_kind(SceneKind kind) {
  if (find_scene_kind(kind.name)) throw std::invalid_argument("scene kind " + kind.name + " is registered already");
  registry().push_back(std::move(kind));
}

const SceneKind* find_scene_kind(const std::string& name) {
  for (const auto& k : scene_kinds())
    if (k.name == name) return &k;
  return nullptr;
}

std::string scene_kind_names() {
  std::string s;
  for (const auto& k : scene_kinds()) s += (s.empty() ? "" : ", ") + k.name;
  return s;
}

std::string scene_kind_of_file(const std::string& path) {
  const auto root = io::TomlTable::parse_file(path);
  const auto sc = root.table("scene");
  if (!sc) root.fail("scene", "required table [scene] is missing");
  return sc->string("kind");
}

std::unique_ptr<Scene> read_scene(const std::string& path) {
  const auto root = io::TomlTable::parse_file(path);
  const auto sc = root.table("scene");
  if (!sc) root.fail("scene", "required table [scene] is missing");
  const std::string kind = sc->string("kind");
  const SceneKind* k = find_scene_kind(kind);
  if (!k) sc->fail("kind", "unknown scene kind (known: " + scene_kind_names() + ")");
  try {
    return k->read(path);
  } catch (const io::InputError& e) {
    throw with_kind_hint(e, path, kind);
  }
}

io::InputError with_kind_hint(const io::InputError& e, const std::string& path, const std::string& kind) {
  // TomlTable::allow_only on the file's top level: key "contact", value "{table}" (an array of
  // tables, [[path]]: "[{table}, ...]").
  const bool table = e.value().rfind("{table}", 0) == 0 || e.value().rfind("[{table}", 0) == 0;
  if (!table || e.file() != path || e.key().find_first_of(".[") != std::string::npos || e.message().rfind("unknown key", 0) != 0) return e;
  std::string takers;
  for (const auto& k : scene_kinds())
    if (std::any_of(k.inputs.begin(), k.inputs.end(), [&](const io::InputInfo& in) { return in.table() == e.key(); }))
      takers += (takers.empty() ? "" : ", ") + k.name;
  // "unknown key (allowed: scene solver)" -> "its tables: scene, solver"
  std::string message = "[" + e.key() + "] is not a table of scene kind " + kind;
  const std::size_t open = e.message().find("(allowed: "), close = e.message().find(')', open);
  if (open != std::string::npos && close != std::string::npos) {
    std::string allowed = e.message().substr(open + 10, close - open - 10);
    for (std::size_t at = allowed.find(' '); at != std::string::npos; at = allowed.find(' ', at + 2)) allowed.replace(at, 1, ", ");
    message += " (its tables: " + allowed + ")";
  }
  if (!takers.empty()) message += "; it is one of the kinds " + takers;
  return io::InputError(e.file(), e.key(), e.value(), message + ": is scene.kind = \"" + kind + "\" right?");
}

}  // namespace spifit::scene
