#pragma once
// Typed, validated access to a TOML file (toml11 underneath). Every error a user can cause
// is thrown as InputError naming the file, the dotted key and the offending value.
#include "forward/io/input_error.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace spifit::io {

class TomlTable {
 public:
  // Parses the file; a missing file or a syntax error becomes an InputError.
  static TomlTable parse_file(const std::string& path);

  const std::string& file() const;
  // Dotted path of a key in this table, e.g. "swift.K".
  std::string key_path(const std::string& key) const;
  bool has(const std::string& key) const;
  std::vector<std::string> keys() const;  // sorted

  double number(const std::string& key) const;
  double number(const std::string& key, double fallback) const;
  int integer(const std::string& key, int fallback) const;
  std::string string(const std::string& key) const;
  std::string string(const std::string& key, const std::string& fallback) const;
  bool boolean(const std::string& key, bool fallback) const;
  std::vector<double> number_list(const std::string& key) const;
  std::vector<std::string> string_list(const std::string& key) const;
  std::optional<TomlTable> table(const std::string& key) const;
  // [[key]] arrays of tables; empty when absent. Entry i is named "key[i]" in errors.
  std::vector<TomlTable> table_array(const std::string& key) const;

  // Rejects any key not in `allowed` (typos must not be silently ignored).
  void allow_only(const std::vector<std::string>& allowed) const;
  // Text of the value stored at key (for error messages).
  std::string value_text(const std::string& key) const;
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;

 private:
  struct Impl;
  explicit TomlTable(std::shared_ptr<const Impl> impl);
  std::shared_ptr<const Impl> impl_;
};

}  // namespace spifit::io
