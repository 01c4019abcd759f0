#pragma once
// Writes a file atomically: the text goes to ".NAME.tmp" beside it and is renamed over NAME,
// so a killed run never leaves a half-written file under its final name. Throws
// std::runtime_error naming the file on failure.
#include <filesystem>
#include <string>

namespace spifit::io {

void write_file_atomic(const std::filesystem::path& path, const std::string& contents);

}  // namespace spifit::io
