#include "forward/io/output_directory.hpp"

#include "forward/io/input_error.hpp"

#include <fstream>
#include <system_error>

namespace spifit::io {

namespace fs = std::filesystem;

OutputDirectory OutputDirectory::prepare(const std::string& path, bool force) {
  const fs::path p(path);
  std::error_code ec;
  if (fs::exists(p, ec)) {
    if (!fs::is_directory(p, ec)) throw InputError("", "--out", path, "exists and is not a directory");
    const bool empty = fs::is_empty(p, ec);
    if (!empty && !force) throw InputError("", "--out", path, "output directory exists and is not empty; pass --force to replace it");
    if (!empty) {
      for (const auto& entry : fs::directory_iterator(p)) fs::remove_all(entry.path(), ec);
      if (ec) throw InputError("", "--out", path, "cannot clear the output directory: " + ec.message());
    }
  } else {
    fs::create_directories(p, ec);
    if (ec) throw InputError("", "--out", path, "cannot create the output directory: " + ec.message());
  }
  return OutputDirectory(p);
}

void OutputDirectory::write_file(const std::string& name, const std::string& contents) const {
  const fs::path target = path_ / name;
  const fs::path tmp = path_ / ("." + name + ".tmp");
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    if (!f) throw std::runtime_error("cannot write " + tmp.string());
    f << contents;
    if (!f) throw std::runtime_error("cannot write " + tmp.string());
  }
  fs::rename(tmp, target);
}

void OutputDirectory::remove_file(const std::string& name) const {
  std::error_code ec;
  fs::remove(path_ / name, ec);
}

}  // namespace spifit::io
