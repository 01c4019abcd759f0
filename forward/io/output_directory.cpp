#include "forward/io/output_directory.hpp"

#include "forward/io/atomic_file.hpp"
#include "forward/io/input_error.hpp"

#include <fstream>
#include <system_error>

namespace spifit::io {

namespace fs = std::filesystem;

OutputDirectory OutputDirectory::prepare(const std::string& path, bool replace, const std::vector<std::string>& inputs) {
  using R = OutputDirectoryError::Reason;
  const fs::path p(path);
  std::error_code ec;
  if (fs::exists(p, ec)) {
    if (!fs::is_directory(p, ec)) throw OutputDirectoryError(R::not_a_directory, path, "exists and is not a directory");
    const bool empty = fs::is_empty(p, ec);
    if (ec) throw OutputDirectoryError(R::cannot_clear, path, "cannot read the output directory: " + ec.message());
    if (!empty && !replace) throw OutputDirectoryError(R::not_empty, path, "output directory exists and is not empty");
    if (!empty) {
      // Only an earlier spifit result is replaced, never an arbitrary directory, and never one
      // that holds this run's own inputs.
      if (!fs::exists(p / "summary.json", ec)) {
        throw OutputDirectoryError(R::not_spifit_output, path, "only a spifit output directory (one with summary.json) is replaced; this one has none");
      }
      const fs::path dir = fs::weakly_canonical(p, ec);
      for (const auto& in : inputs) {
        const fs::path f = fs::weakly_canonical(in, ec);
        const auto rel = f.lexically_relative(dir);
        if (!rel.empty() && *rel.begin() != "..") {
          throw OutputDirectoryError(R::holds_input, path, "holds an input of this run (" + in + "); choose another output directory");
        }
      }
      std::string failed;
      for (fs::directory_iterator it(p, ec), end; !ec && it != end; it.increment(ec)) {
        std::error_code rm;
        fs::remove_all(it->path(), rm);
        if (rm && failed.empty()) failed = it->path().string() + ": " + rm.message();
      }
      if (ec && failed.empty()) failed = ec.message();
      if (!failed.empty()) throw OutputDirectoryError(R::cannot_clear, path, "cannot clear the output directory: " + failed);
    }
  } else {
    fs::create_directories(p, ec);
    if (ec) throw OutputDirectoryError(R::cannot_create, path, "cannot create the output directory: " + ec.message());
  }
  return OutputDirectory(p);
}

OutputDirectory OutputDirectory::existing(const std::string& path) {
  std::error_code ec;
  if (!fs::is_directory(path, ec))
    throw OutputDirectoryError(OutputDirectoryError::Reason::missing, path, "no output directory to resume (a resume continues an earlier run's directory)");
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
