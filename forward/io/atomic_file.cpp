#include "forward/io/atomic_file.hpp"

#include <fstream>
#include <stdexcept>
#include <system_error>

namespace spifit::io {

void write_file_atomic(const std::filesystem::path& path, const std::string& contents) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (path.has_parent_path()) fs::create_directories(path.parent_path(), ec);
  // Built by appending: "." + std::string trips GCC 12's false -Wrestrict (GCC bug 105651).
  std::string tmp_name = ".";
  tmp_name += path.filename().string();
  tmp_name += ".tmp";
  const fs::path tmp = path.parent_path() / tmp_name;
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    if (!f) throw std::runtime_error("cannot write " + tmp.string());
    f << contents;
    if (!f) throw std::runtime_error("cannot write " + tmp.string());
  }
  fs::rename(tmp, path, ec);
  if (ec) throw std::runtime_error("cannot write " + path.string() + ": " + ec.message());
}

}  // namespace spifit::io
