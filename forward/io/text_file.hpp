#pragma once
// Reading a whole user-supplied text file (G-code, tool-path CSV): a missing, unreadable or
// directory path is an io::InputError naming the file.
#include <string>

namespace spifit::io {

std::string read_text_file(const std::string& path);

}  // namespace spifit::io
