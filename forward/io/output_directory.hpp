#pragma once
// An output directory that never silently overwrites earlier results: an existing,
// non-empty directory is refused unless replace is set; then it is cleared only if it is
// an earlier spifit output (it holds summary.json) and holds none of this run's inputs. Files are written atomically (temporary + rename), so a
// killed run never leaves a half-written file under its final name.
#include "forward/io/input_error.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace spifit::io {

// Why an output directory cannot be used; the key of the InputError is "output directory" (a
// command line names its own option for it).
class OutputDirectoryError : public InputError {
 public:
  enum class Reason { not_a_directory, not_empty, not_spifit_output, holds_input, cannot_clear, cannot_create, missing };
  OutputDirectoryError(Reason reason, const std::string& path, const std::string& message)
      : InputError("", "output directory", path, message), reason_(reason) {}
  Reason reason() const { return reason_; }

 private:
  Reason reason_;
};

class OutputDirectory {
 public:
  // Throws OutputDirectoryError when the directory exists and replace is false, or it cannot be
  // replaced. inputs: files this run reads (scene, card), which must not lie inside the directory.
  static OutputDirectory prepare(const std::string& path, bool replace, const std::vector<std::string>& inputs = {});
  // An existing output directory whose run is to be continued (a resume); nothing is cleared.
  // Throws OutputDirectoryError when it does not exist or is not a directory.
  static OutputDirectory existing(const std::string& path);

  const std::filesystem::path& path() const { return path_; }
  void write_file(const std::string& name, const std::string& contents) const;
  void remove_file(const std::string& name) const;

 private:
  explicit OutputDirectory(std::filesystem::path p) : path_(std::move(p)) {}
  std::filesystem::path path_;
};

}  // namespace spifit::io
