#pragma once
// The harness of a file reader under libFuzzer: the input bytes are written to a file (the
// readers take paths: error messages name them) and read; an input error (io::InputError) or
// any other std::exception is a verdict the reader may give, a crash, a hang or a sanitizer
// report is a bug. Build: cmake -S . -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DSPIFIT_FUZZ=ON
// (tests/fuzz/README.md).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <exception>
#include <fstream>
#include <string>

namespace spifit::fuzz {

// A file of its own per process in a copy of the bundled tree (SPIFIT_FUZZ_WORK: links to the
// source's materials, scenes and data, tests/fuzz/CMakeLists.txt), so that the paths a scene or
// fit file names relative to itself resolve as in experiments/aa3003o/ and the readers get past
// them. folder: "scenes" (scenes, cards, G-code, CSV) or "" (fit files, beside scenes/ and data/).
inline std::string input_path(const char* folder, const char* extension) {
  const std::string dir = std::string(SPIFIT_FUZZ_WORK) + "/experiments/aa3003o/" + folder;
  return dir + (*folder ? "/" : "") + "fuzz_" + std::to_string(::getpid()) + extension;
}

template <typename Read>
int read_bytes_as_file(const std::uint8_t* data, std::size_t size, const char* extension, Read read, const char* folder = "scenes") {
  static const std::string path = input_path(folder, extension);
  {
    std::ofstream f(path, std::ios::binary | std::ios::trunc);
    f.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    read(path);
  } catch (const std::exception&) {
    // A verdict on bad input: fine.
  }
  return 0;
}

}  // namespace spifit::fuzz
