#include "cli/cli_errors.hpp"

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

io::OutputDirectory prepare_output(const std::string& out, bool force, const std::vector<std::string>& inputs) {
  try {
    return io::OutputDirectory::prepare(out, force, inputs);
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
