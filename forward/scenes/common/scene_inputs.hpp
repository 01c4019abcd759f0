#pragma once
// What every kind's reader shares (docs/design/architecture.md, "A new scene kind"): the [scene] keys
// kind, name, description and material in its input table, reading name, description and card,
// and letting the input table read the TOML tables it declares.
#include "forward/io/named_inputs.hpp"
#include "forward/io/toml_reader.hpp"
#include "forward/scenes/common/scene_tables.hpp"

#include <filesystem>
#include <initializer_list>
#include <string>
#include <vector>

namespace spifit::scene {

// How a kind's files give [scene] material: not at all (a shell benchmark), always, or with
// the default card.
enum class SceneMaterialKey { none, required, optional };

// Declares scene.kind (one of `kinds`), scene.name, scene.description and scene.material.
template <typename Scene>
void add_scene_inputs(io::InputTable<Scene>& t, std::vector<std::string> kinds, SceneMaterialKey material) {
  using io::InputType;
  t.custom({"scene.kind", {}, "", {}, std::move(kinds), "the scene kind (required)", false}, InputType::text);
  t.custom({"scene.name", {}, "", {}, {}, "name in outputs (default: the file's stem)", false}, InputType::text);
  t.custom({"scene.description", {}, "", {}, {}, "free text", false}, InputType::text);
  if (material == SceneMaterialKey::none) return;
  const std::string when = material == SceneMaterialKey::required ? "required" : "default: card C.3 + C.4";
  t.custom({"scene.material", {}, "", {}, {}, "material card, relative to the scene file (" + when + ")", false}, InputType::text);
}

// [scene] name (default: the file's stem) and description of the scene file at `path` into
// s.name and s.description.
template <typename Scene>
void read_scene_name(const io::TomlTable& sc, const std::string& path, Scene& s) {
  s.name = sc.string("name", std::filesystem::path(path).stem().string());
  s.description = sc.string("description", "");
}

// The name, description and material card of the scene file at `path` into s.name,
// s.description and s.card.
template <typename Scene>
void read_scene_header(const io::TomlTable& sc, const std::string& path, Scene& s, bool card_required = false) {
  read_scene_name(sc, path, s);
  s.card = read_scene_material(sc, path, card_required);
}

// Each of `tables` the file has: its keys must be the input table's (allow_only), which reads
// and checks them into s.
template <typename Scene>
void read_input_tables(const io::TomlTable& root, const io::InputTable<Scene>& inputs, std::initializer_list<const char*> tables, Scene& s) {
  for (const char* table : tables) {
    const auto t = root.table(table);
    if (!t) continue;
    t->allow_only(inputs.keys_of(table));
    inputs.read(*t, table, s);
  }
}

}  // namespace spifit::scene
