#pragma once
// Errors of the libraries in the words of the command line: a library names its option fields
// and "output directory"; the commands name their options (--out, --bin, ...) and how to get past
// the error (--force, --resume).
#include "forward/io/input_error.hpp"
#include "forward/io/output_directory.hpp"

#include <map>
#include <string>
#include <vector>

namespace spifit::cli {

// io::OutputDirectory::prepare / existing with their errors on --out. prepare_output warns on
// stderr (unless quiet) of the entries --force kept because spifit did not write them; both note
// a lock taken over from a process that ended while it wrote there. existing_output (a resume of
// the scene or fit file `input`) refuses a directory whose run of that file is complete.
io::OutputDirectory prepare_output(const std::string& out, bool force, const std::vector<std::string>& inputs, bool quiet);
io::OutputDirectory existing_output(const std::string& out, const std::string& input, bool quiet);

// Runs f; an io::InputError without a file whose key is a field in `options` is rethrown with
// the key of the command-line option (field -> option).
template <typename F>
auto with_option_names(const std::map<std::string, std::string>& options, F f) {
  try {
    return f();
  } catch (const io::InputError& e) {
    const auto it = options.find(e.key());
    if (!e.file().empty() || it == options.end()) throw;
    throw io::InputError("", it->second, e.value(), e.message());
  }
}

}  // namespace spifit::cli
