#pragma once
// Progress of a long run, reported through a callback the caller supplies (the CLI prints the
// lines with --verbose); library code never prints.
#include <functional>
#include <string>

namespace spifit::scene {

struct ProgressEvent {
  enum class Kind { increment, mark, checkpoint, note };
  Kind kind = Kind::note;
  std::string text;       // one line, no newline; may be empty (an increment: the fraction only)
  double fraction = 0.0;  // of the run's path, in [0, 1]
};

using ProgressSink = std::function<void(const ProgressEvent&)>;

}  // namespace spifit::scene
