#include "forward/io/output_directory.hpp"

#include "forward/io/atomic_file.hpp"
#include "forward/io/host_and_time.hpp"
#include "forward/io/input_error.hpp"
#include "forward/io/text_file.hpp"

#include <algorithm>
#include <mutex>
#include <set>
#include <sstream>
#include <system_error>

namespace spifit::io {

namespace fs = std::filesystem;

namespace {

// What spifit writes at the top of an output directory: what --force removes from a directory
// of an older spifit, which kept no manifest (summary.json marks it as one).
const std::set<std::string> kSpifitOutputNames{
    "summary.json", "curve.csv",  "increments.csv", "force.csv",   "energies.csv", "contours.csv", "sections.csv",     "history.csv",
    "stages.csv",   "sections",   "vtu",            "checkpoint",  "fit.json",     "card.toml",    "experiments",      "exports",
    "report.md",    "report.html", "plots",         "runs",        "sweep.csv",    "sensitivities.csv", "points",      "section.csv"};

// write_file_atomic's temporary of NAME (left behind by a killed write).
bool is_temporary(const std::string& name) { return name.size() > 5 && name[0] == '.' && name.compare(name.size() - 4, 4, ".tmp") == 0; }

// A manifest line that names an entry of the directory itself (nothing outside it, nothing nested).
bool plain_entry(const std::string& name) { return !name.empty() && name != "." && name != ".." && name.find('/') == std::string::npos; }

// The entries of dir but its lock file, which belongs to whoever writes there now.
std::vector<std::string> entries(const fs::path& dir, std::error_code& ec) {
  std::vector<std::string> out;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    std::string name = it->path().filename().string();
    if (name != DirectoryLock::kFile) out.push_back(std::move(name));
  }
  std::sort(out.begin(), out.end());
  return out;
}

// The directory's lock, or the OutputDirectoryError that says who holds it.
std::shared_ptr<DirectoryLock> lock_directory(const fs::path& p, const std::string& path) {
  using R = OutputDirectoryError::Reason;
  DirectoryLock::Refusal refusal;
  std::shared_ptr<DirectoryLock> lock = DirectoryLock::take(p, &refusal);
  if (lock) return lock;
  switch (refusal.reason) {
    case DirectoryLock::Refusal::Reason::held: {
      const DirectoryLock::Holder& h = refusal.holder;
      const bool here = h.host.empty() || h.host == host_name();
      throw OutputDirectoryError(R::locked, path,
                                 "in use: a live spifit process is writing there (" + h.describe() + "); wait for it to end, or stop it (" +
                                     (here ? "kill " + std::to_string(h.pid) : "on host " + h.host) + ") and try again");
    }
    case DirectoryLock::Refusal::Reason::permission_denied:
      throw OutputDirectoryError(R::permission_denied, path, "permission denied: cannot write in the output directory (" + refusal.message + ")");
    case DirectoryLock::Refusal::Reason::cannot_create: break;
  }
  throw OutputDirectoryError(R::cannot_create, path, "cannot lock the output directory: " + refusal.message);
}

std::set<std::string> read_manifest(const fs::path& file) {
  std::set<std::string> listed;
  std::istringstream in(read_text_file(file.string()));
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    if (line.back() == '/') line.pop_back();
    if (plain_entry(line)) listed.insert(line);
  }
  return listed;
}

}  // namespace

struct OutputDirectory::Manifest {
  fs::path file;
  std::set<std::string> listed;   // top-level entries spifit wrote
  std::set<std::string> foreign;  // entries that were there, not spifit's: never listed
  std::mutex mutex;

  // Adds name; rewrites the file when it is new. Call with the mutex held.
  void add(const std::string& name, const fs::path& dir) {
    if (!plain_entry(name) || name == kManifest || name == DirectoryLock::kFile || is_temporary(name) || foreign.count(name) || !listed.insert(name).second) return;
    write(dir);
  }
  void write(const fs::path& dir) const {
    std::string text = "# spifit output directory: the entries spifit wrote here, one per line (a directory ends in /).\n"
                       "# `--force` removes these and nothing else (docs/reference/file-formats.md, \"Output directories\").\n";
    for (const auto& n : listed) text += n + (fs::is_directory(dir / n) ? "/" : "") + "\n";
    write_file_atomic(file, text);
  }
};

OutputDirectory::OutputDirectory(fs::path p, std::shared_ptr<Manifest> m, std::vector<std::string> kept, std::shared_ptr<DirectoryLock> lock)
    : path_(std::move(p)), manifest_(std::move(m)), kept_(std::move(kept)), lock_(std::move(lock)) {}

OutputDirectory OutputDirectory::prepare(const std::string& path, bool replace, const std::vector<std::string>& inputs, Locking locking) {
  using R = OutputDirectoryError::Reason;
  const fs::path p(path);
  std::error_code ec;
  std::vector<std::string> kept;
  std::shared_ptr<DirectoryLock> lock;
  if (fs::exists(p, ec)) {
    if (!fs::is_directory(p, ec)) throw OutputDirectoryError(R::not_a_directory, path, "exists and is not a directory");
    const bool empty = entries(p, ec).empty();
    if (ec) {
      const bool denied = ec == std::errc::permission_denied || ec == std::errc::operation_not_permitted;
      throw OutputDirectoryError(denied ? R::permission_denied : R::cannot_clear, path,
                                 std::string(denied ? "permission denied: " : "") + "cannot read the output directory: " + ec.message());
    }
    if (!empty && !replace) {
      // A live run's directory: say so, rather than suggest replacing it.
      if (locking == Locking::take) lock = lock_directory(p, path);
      throw OutputDirectoryError(R::not_empty, path, "output directory exists and is not empty");
    }
    if (!empty) {
      // Only what an earlier spifit run wrote is removed, never an arbitrary directory, and never
      // one that holds this run's own inputs.
      std::set<std::string> remove;
      if (fs::exists(p / kManifest, ec)) {
        remove = read_manifest(p / kManifest);
        remove.insert(kManifest);
      } else if (fs::exists(p / "summary.json", ec)) {
        remove = kSpifitOutputNames;
      } else {
        throw OutputDirectoryError(R::not_spifit_output, path,
                                   "only a spifit output directory (one with .spifit-manifest or summary.json) is replaced; this one has neither");
      }
      const fs::path dir = fs::weakly_canonical(p, ec);
      for (const auto& in : inputs) {
        const fs::path f = fs::weakly_canonical(in, ec);
        const auto rel = f.lexically_relative(dir);
        if (!rel.empty() && *rel.begin() != "..") {
          throw OutputDirectoryError(R::holds_input, path, "holds an input of this run (" + in + "); choose another output directory");
        }
      }
      // Nothing is removed while another process writes there.
      if (locking == Locking::take) lock = lock_directory(p, path);
      std::string failed;
      for (const auto& name : entries(p, ec)) {
        const bool spifit = remove.count(name) || (is_temporary(name) && remove.count(name.substr(1, name.size() - 5)));
        if (!spifit) {
          kept.push_back(name);
          continue;
        }
        std::error_code rm;
        fs::remove_all(p / name, rm);
        if (rm && failed.empty()) failed = (p / name).string() + ": " + rm.message();
      }
      if (ec && failed.empty()) failed = ec.message();
      if (!failed.empty()) throw OutputDirectoryError(R::cannot_clear, path, "cannot clear the output directory: " + failed);
    }
  } else {
    fs::create_directories(p, ec);
    if (ec) {
      const bool denied = ec == std::errc::permission_denied || ec == std::errc::operation_not_permitted || ec == std::errc::read_only_file_system;
      throw OutputDirectoryError(denied ? R::permission_denied : R::cannot_create, path,
                                 std::string(denied ? "permission denied: " : "") + "cannot create the output directory: " + ec.message());
    }
  }
  if (locking == Locking::take && !lock) lock = lock_directory(p, path);
  auto m = std::make_shared<Manifest>();
  m->file = p / kManifest;
  m->foreign.insert(kept.begin(), kept.end());
  m->write(p);
  return OutputDirectory(p, std::move(m), std::move(kept), std::move(lock));
}

OutputDirectory OutputDirectory::existing(const std::string& path, Locking locking) {
  std::error_code ec;
  if (!fs::is_directory(path, ec))
    throw OutputDirectoryError(OutputDirectoryError::Reason::missing, path, "no output directory to resume (a resume continues an earlier run's directory)");
  const fs::path p(path);
  std::shared_ptr<DirectoryLock> lock = locking == Locking::take ? lock_directory(p, path) : nullptr;
  if (!fs::exists(p / kManifest, ec)) return OutputDirectory(p, nullptr, {}, std::move(lock));
  auto m = std::make_shared<Manifest>();
  m->file = p / kManifest;
  m->listed = read_manifest(m->file);
  for (const auto& name : entries(p, ec))
    if (name != kManifest && !is_temporary(name) && !m->listed.count(name)) m->foreign.insert(name);
  return OutputDirectory(p, std::move(m), {}, std::move(lock));
}

void OutputDirectory::write_file(const std::string& name, const std::string& contents) const {
  write_file_atomic(path_ / name, contents);
  if (!manifest_) return;
  const std::lock_guard<std::mutex> lock(manifest_->mutex);
  manifest_->add(fs::path(name).begin()->string(), path_);
}

void OutputDirectory::record() const {
  if (!manifest_) return;
  const std::lock_guard<std::mutex> lock(manifest_->mutex);
  std::error_code ec;
  for (const auto& name : entries(path_, ec)) manifest_->add(name, path_);
}

void OutputDirectory::remove_file(const std::string& name) const {
  std::error_code ec;
  fs::remove(path_ / name, ec);
}

}  // namespace spifit::io
