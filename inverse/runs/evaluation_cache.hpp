#pragma once
// The evaluations of a fit's FE experiments kept on disk (DIR/runs/evaluations.jsonl), so that a
// fit that was killed and is resumed (`spifit fit --resume`) recomputes none of the forward runs
// it had finished: each line holds an experiment's name, the exact parameter point and its
// residuals (17 significant digits: the same bits read back), so the resumed fit takes the same
// steps and ends where an uninterrupted one does. The first line states a signature of the
// fit's input files; a resume with other inputs is refused.
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace spifit::inverse {

class EvaluationCache {
 public:
  struct Entry {
    bool ok = false;
    std::vector<double> residuals;
  };

  // A new cache at `file` (resume = false: an existing file is replaced) or the one there
  // (resume = true): io::InputError naming the file when it is missing or its signature differs.
  EvaluationCache(const std::filesystem::path& file, const std::string& signature, bool resume);

  std::optional<Entry> find(const std::string& experiment, const std::string& point) const;
  // Appends and flushes one line (thread-safe).
  void add(const std::string& experiment, const std::string& point, const Entry& e);
  std::size_t loaded() const { return loaded_; }  // entries read back on a resume

 private:
  mutable std::mutex mutex_;
  std::map<std::string, Entry> entries_;  // "experiment point"
  std::ofstream out_;
  std::size_t loaded_ = 0;
};

// FNV-1a over the contents of the files (fit file, card, scenes, data): the signature a resume
// checks. std::runtime_error for a file that cannot be read.
std::string files_signature(const std::vector<std::string>& files);

}  // namespace spifit::inverse
