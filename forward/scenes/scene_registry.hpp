#pragma once
// Every scene kind spifit knows (common/scene.hpp), by name: what `spifit run`, `sweep`,
// `synth`, `inputs` and fits look a scene file's [scene] kind up in. A new kind is a folder of
// its own plus its line in scene_registry.cpp (docs/design/architecture.md).
#include "forward/scenes/common/scene.hpp"

#include <deque>
#include <memory>
#include <string>
#include <vector>

namespace spifit::scene {

// In registration order; references stay valid as kinds are added.
const std::deque<SceneKind>& scene_kinds();
// Adds a kind defined outside this library (an extension, a test's example kind);
// std::invalid_argument when its name is taken. Call before the kind is used.
void register_scene_kind(SceneKind kind);
// nullptr for an unknown name.
const SceneKind* find_scene_kind(const std::string& name);
// "tensile, shear, ..., cone"
std::string scene_kind_names();

// The [scene] kind of a scene file; io::InputError for a missing file, a syntax error or a
// missing kind.
std::string scene_kind_of_file(const std::string& path);
// Reads a scene file of any kind; io::InputError naming the file and key (an unknown kind lists
// the known ones; a table the kind does not take, as [contact] in a file of kind tensile, names
// the kinds that take it: with_kind_hint).
std::unique_ptr<Scene> read_scene(const std::string& path);
// When the reader of kind refused a whole table of the scene file at path as an unknown key, the
// kind, not the table, may be the typo: e with the kinds that take that table and the question
// whether scene.kind is right. Any other error as it is.
io::InputError with_kind_hint(const io::InputError& e, const std::string& path, const std::string& kind);

}  // namespace spifit::scene
