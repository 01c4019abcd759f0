#pragma once
// An output directory that never silently overwrites earlier results, nor removes what spifit
// did not write. spifit lists the top-level entries it creates in DIR/.spifit-manifest (a file or
// a whole subdirectory per line). An existing, non-empty directory is refused unless replace is
// set; then it must hold none of this run's inputs, and
//   - with a manifest: only the entries listed in it are removed (a user's own files beside them
//     are kept and reported by kept());
//   - without one (an earlier spifit's output: it holds summary.json): only entries with the
//     names of spifit's outputs (summary.json, force.csv, vtu/, ...) are removed, the rest kept;
//   - neither: refused, it is not a spifit output.
// Files are written atomically (temporary + rename), so a killed run never leaves a half-written
// file under its final name. One writer at a time: prepare() and existing() take the directory's
// lock (directory_lock.hpp) before they change anything, and refuse a directory another live
// process holds, replace or not. Format: docs/reference/file-formats.md, "Output directories".
#include "forward/io/directory_lock.hpp"
#include "forward/io/input_error.hpp"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace spifit::io {

// Why an output directory cannot be used; the key of the InputError is "output directory" (a
// command line names its own option for it).
class OutputDirectoryError : public InputError {
 public:
  enum class Reason { not_a_directory, not_empty, not_spifit_output, holds_input, cannot_clear, cannot_create, missing, locked, permission_denied };
  OutputDirectoryError(Reason reason, const std::string& path, const std::string& message)
      : InputError("", "output directory", path, message), reason_(reason) {}
  Reason reason() const { return reason_; }

 private:
  Reason reason_;
};

class OutputDirectory {
 public:
  static constexpr const char* kManifest = ".spifit-manifest";

  // take: the directory's lock, held by this object and its copies (a process that writes on
  // behalf of the lock's holder, such as a sweep point's job, or a subdirectory of a locked
  // directory: none).
  enum class Locking { take, none };

  // Throws OutputDirectoryError when the directory exists and replace is false, or it cannot be
  // replaced, or another live process holds its lock. inputs: files this run reads (scene,
  // card), which must not lie inside the directory.
  static OutputDirectory prepare(const std::string& path, bool replace, const std::vector<std::string>& inputs = {},
                                 Locking locking = Locking::take);
  // An existing output directory whose run is to be continued (a resume); nothing is cleared.
  // Its manifest, if any, goes on listing what the run adds. Throws OutputDirectoryError when it
  // does not exist or is not a directory, or another live process holds its lock.
  static OutputDirectory existing(const std::string& path, Locking locking = Locking::take);

  const std::filesystem::path& path() const { return path_; }
  // Atomic write of DIR/name (subdirectories created), listed in the manifest.
  void write_file(const std::string& name, const std::string& contents) const;
  void remove_file(const std::string& name) const;
  // Lists in the manifest the top-level entries that appeared since the directory was prepared
  // or opened (for files written by other means than write_file: vtu/, checkpoint/, plots/).
  void record() const;
  // Entries prepare() found but did not remove (not written by spifit), for a warning.
  const std::vector<std::string>& kept() const { return kept_; }
  // The holder of a lock this directory's lock replaced: a process that ended while it wrote here.
  std::optional<DirectoryLock::Holder> lock_taken_over() const { return lock_ ? lock_->taken_over() : std::nullopt; }

 private:
  struct Manifest;
  OutputDirectory(std::filesystem::path p, std::shared_ptr<Manifest> m, std::vector<std::string> kept, std::shared_ptr<DirectoryLock> lock);
  std::filesystem::path path_;
  std::shared_ptr<Manifest> manifest_;  // null: no manifest is kept (a directory of an older spifit, resumed)
  std::vector<std::string> kept_;
  std::shared_ptr<DirectoryLock> lock_;  // null: Locking::none
};

}  // namespace spifit::io
