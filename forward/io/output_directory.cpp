#include "forward/io/output_directory.hpp"

#include "forward/io/atomic_file.hpp"
#include "forward/io/input_error.hpp"

#include <fstream>
#include <system_error>

namespace spifit::io {

namespace fs = std::filesystem;

OutputDirectory OutputDirectory::prepare(const std::string& path, bool force, const std::vector<std::string>& inputs) {
  const fs::path p(path);
  std::error_code ec;
  if (fs::exists(p, ec)) {
    if (!fs::is_directory(p, ec)) throw InputError("", "--out", path, "exists and is not a directory");
    const bool empty = fs::is_empty(p, ec);
    if (ec) throw InputError("", "--out", path, "cannot read the output directory: " + ec.message());
    if (!empty && !force) throw InputError("", "--out", path, "output directory exists and is not empty; pass --force to replace it");
    if (!empty) {
      // --force replaces an earlier spifit result, never an arbitrary directory, and never
      // one that holds this run's own inputs.
      if (!fs::exists(p / "summary.json", ec)) {
        throw InputError("", "--out", path, "--force only replaces a spifit output directory (one with summary.json); this one has none");
      }
      const fs::path dir = fs::weakly_canonical(p, ec);
      for (const auto& in : inputs) {
        const fs::path f = fs::weakly_canonical(in, ec);
        const auto rel = f.lexically_relative(dir);
        if (!rel.empty() && *rel.begin() != "..") {
          throw InputError("", "--out", path, "holds an input of this run (" + in + "); choose another output directory");
        }
      }
      std::string failed;
      for (fs::directory_iterator it(p, ec), end; !ec && it != end; it.increment(ec)) {
        std::error_code rm;
        fs::remove_all(it->path(), rm);
        if (rm && failed.empty()) failed = it->path().string() + ": " + rm.message();
      }
      if (ec && failed.empty()) failed = ec.message();
      if (!failed.empty()) throw InputError("", "--out", path, "cannot clear the output directory: " + failed);
    }
  } else {
    fs::create_directories(p, ec);
    if (ec) throw InputError("", "--out", path, "cannot create the output directory: " + ec.message());
  }
  return OutputDirectory(p);
}

OutputDirectory OutputDirectory::existing(const std::string& path) {
  std::error_code ec;
  if (!fs::is_directory(path, ec)) throw InputError("", "--out", path, "no output directory to resume (--resume continues an earlier run's directory)");
  return OutputDirectory(fs::path(path));
}

void OutputDirectory::write_file(const std::string& name, const std::string& contents) const {
  write_file_atomic(path_ / name, contents);
}

void OutputDirectory::remove_file(const std::string& name) const {
  std::error_code ec;
  fs::remove(path_ / name, ec);
}

}  // namespace spifit::io
