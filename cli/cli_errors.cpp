#include "cli/cli_errors.hpp"

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

}  // namespace

io::OutputDirectory prepare_output(const std::string& out, bool force, const std::vector<std::string>& inputs, bool quiet) {
  try {
    auto dir = io::OutputDirectory::prepare(out, force, inputs);
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

io::OutputDirectory existing_output(const std::string& out) {
  try {
    return io::OutputDirectory::existing(out);
  } catch (const io::OutputDirectoryError& e) {
    on_out(e);
  }
}

}  // namespace spifit::cli
