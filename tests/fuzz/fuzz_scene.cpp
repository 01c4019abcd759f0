// Scene files of every kind (and the material cards they name): forward/scenes/scene_registry.hpp.
#include "forward/scenes/scene_registry.hpp"
#include "tests/fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return spifit::fuzz::read_bytes_as_file(data, size, ".toml", [](const std::string& p) { (void)spifit::scene::read_scene(p); });
}
