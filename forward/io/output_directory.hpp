#pragma once
// An output directory that never silently overwrites earlier results: an existing,
// non-empty directory is refused unless force is set; with force it is cleared only if it is
// an earlier spifit output (it holds summary.json) and holds none of this run's inputs. Files are written atomically (temporary + rename), so a
// killed run never leaves a half-written file under its final name.
#include <filesystem>
#include <string>
#include <vector>

namespace spifit::io {

class OutputDirectory {
 public:
  // Throws InputError (key "--out") when the directory exists and force is false.
  // inputs: files this run reads (scene, card), which must not lie inside the directory.
  static OutputDirectory prepare(const std::string& path, bool force, const std::vector<std::string>& inputs = {});
  // An existing output directory whose run is to be continued (--resume); nothing is cleared.
  // Throws InputError (key "--out") when it does not exist or is not a directory.
  static OutputDirectory existing(const std::string& path);

  const std::filesystem::path& path() const { return path_; }
  void write_file(const std::string& name, const std::string& contents) const;
  void remove_file(const std::string& name) const;

 private:
  explicit OutputDirectory(std::filesystem::path p) : path_(std::move(p)) {}
  std::filesystem::path path_;
};

}  // namespace spifit::io
