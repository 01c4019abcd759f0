#pragma once
// Where a run writes its files: an output directory, or nowhere (a run kept in memory, as an
// identification or a sweep runs a scene when it needs only the typed result).
#include "forward/io/output_directory.hpp"

#include <string>

namespace spifit::scene {

class RunFiles {
 public:
  RunFiles() = default;  // nothing is written
  explicit RunFiles(const io::OutputDirectory& out) : out_(&out) {}
  bool enabled() const { return out_ != nullptr; }
  const io::OutputDirectory* directory() const { return out_; }
  // Atomic write of DIR/name (subdirectories created); nothing without a directory.
  void write(const std::string& name, const std::string& contents) const {
    if (out_) out_->write_file(name, contents);
  }

 private:
  const io::OutputDirectory* out_ = nullptr;
};

}  // namespace spifit::scene
