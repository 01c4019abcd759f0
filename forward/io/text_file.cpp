#include "forward/io/text_file.hpp"

#include "forward/io/input_error.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace spifit::io {

std::string read_text_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(path, "", "", "cannot read file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "", "cannot read file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(path, "", "", "cannot read file");
  return text.str();
}

}  // namespace spifit::io
