#include "forward/scenes/scene_registry.hpp"

#include "forward/io/toml_reader.hpp"
#include "forward/scenes/benchmark/shell_benchmark_kind.hpp"
#include "forward/scenes/cone/cone_kind.hpp"
#include "forward/scenes/forming/forming_kind.hpp"
#include "forward/scenes/material_point/material_point_kind.hpp"

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
  return k->read(path);
}

}  // namespace spifit::scene
