#include "cli/cli_errors.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <iostream>

namespace spifit::cli {
namespace {

[[noreturn]] void on_out(const io::OutputDirectoryError& e) {
  using R = io::OutputDirectoryError::Reason;
  std::string hint;
  if (e.reason() == R::not_empty) hint = "; pass --force to replace it";
  if (e.reason() == R::not_spifit_output) hint = " (--force replaces only those)";
  if (e.reason() == R::missing) hint = " (--resume continues a run in the directory it wrote)";
  throw io::InputError("", "--out", e.value(), e.message() + hint);
}

// A lock left by a process that ended while it wrote in the directory (killed, or crashed).
void note_taken_over(const io::OutputDirectory& dir, const std::string& out, bool quiet) {
  if (quiet) return;
  if (const auto h = dir.lock_taken_over())
    std::cerr << "spifit: note: --out = " << out << ": the run that wrote there before (" << h->describe()
              << ") ended without releasing it (killed?); taking it over\n";
}

}  // namespace

io::OutputDirectory prepare_output(const std::string& out, bool force, const std::vector<std::string>& inputs, bool quiet) {
  try {
    auto dir = io::OutputDirectory::prepare(out, force, inputs);
    note_taken_over(dir, out, quiet);
    if (!quiet && !dir.kept().empty()) {
      std::string names;
      for (const auto& n : dir.kept()) names += (names.empty() ? "" : ", ") + n;
      std::cerr << "spifit: warning: --out = " << out << ": kept " << io::one_line(names) << " (not written by spifit: --force removes only what "
                << io::OutputDirectory::kManifest << " lists)\n";
    }
    return dir;
  } catch (const io::OutputDirectoryError& e) {
    on_out(e);
  }
}

io::OutputDirectory existing_output(const std::string& out, const std::string& input, bool quiet) {
  // A run of this scene (or fit) that ended well has nothing left to do: say so, not "no
  // checkpoint". (Another scene's run: the resume names the mismatch.)
  std::ifstream in(std::filesystem::path(out) / "summary.json");
  if (in) {
    const auto j = nlohmann::json::parse(in, nullptr, false);
    const auto same = [&](const char* key) {
      std::error_code ec;
      const std::string file = j.is_object() ? j.value(key, "") : "";
      return !file.empty() && std::filesystem::weakly_canonical(file, ec) == std::filesystem::weakly_canonical(input, ec);
    };
    if (j.is_object() && j.value("status", "") == "ok" && (same("scene_file") || same("fit_file")))
      throw io::InputError("", "--resume", out,
                           "the run in this directory is complete (summary.json: status ok): nothing to resume; to run it again, pass --force instead");
  }
  try {
    auto dir = io::OutputDirectory::existing(out);
    note_taken_over(dir, out, quiet);
    return dir;
  } catch (const io::OutputDirectoryError& e) {
    on_out(e);
  }
}

}  // namespace spifit::cli
