#pragma once
// An output directory that never silently overwrites earlier results: an existing,
// non-empty directory is refused unless force is set (then its old contents are removed
// before anything new is written). Files are written atomically (temporary + rename), so a
// killed run never leaves a half-written file under its final name.
#include <filesystem>
#include <string>

namespace spifit::io {

class OutputDirectory {
 public:
  // Throws InputError (key "--out") when the directory exists and force is false.
  static OutputDirectory prepare(const std::string& path, bool force);

  const std::filesystem::path& path() const { return path_; }
  void write_file(const std::string& name, const std::string& contents) const;
  void remove_file(const std::string& name) const;

 private:
  explicit OutputDirectory(std::filesystem::path p) : path_(std::move(p)) {}
  std::filesystem::path path_;
};

}  // namespace spifit::io
