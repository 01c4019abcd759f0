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
  // The run's load factor in [0, 1]: the path with the tool's moves through the air shortened (a
  // cone's pie moves, cone_load_map.hpp), so nearer the work done than the fraction of the path;
  // what an estimate of the time left goes by.
  double load = 0.0;
};

using ProgressSink = std::function<void(const ProgressEvent&)>;

}  // namespace spifit::scene
