#pragma once
// A small versioned binary archive for run state (checkpoints): little-endian, doubles stored
// as their IEEE-754 bit patterns (bit-exact round trip), named sections to catch a reader that
// runs out of step with its writer, and a 64-bit FNV-1a checksum over everything before it,
// so a truncated or corrupted file is refused before any of it is used.
//
// Layout: "SPIFITAR" | u32 archive format version | string kind | u32 kind version |
//         payload (u32, i64, f64, strings = u64 length + bytes, vectors = u64 count + items,
//         sections = tag strings) | u64 checksum.
// Readers throw ArchiveError (what went wrong and where); the caller names the file.
#include <Eigen/Core>

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace spifit::io {

class ArchiveError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// 64-bit FNV-1a of a byte string (checksums, input identity).
std::uint64_t fnv1a64(std::string_view bytes, std::uint64_t seed = 0xcbf29ce484222325ULL);

class BinaryWriter {
 public:
  static constexpr std::uint32_t kFormatVersion = 1;
  // kind names what the archive holds ("cone-checkpoint"); kind_version its layout.
  BinaryWriter(const std::string& kind, std::uint32_t kind_version);

  void u32(std::uint32_t v);
  void i64(std::int64_t v);
  void f64(double v);
  void boolean(bool v);
  void string(const std::string& s);
  void section(const std::string& tag);  // a named mark the reader checks
  void vec3(const Eigen::Vector3d& v);
  void f64s(const std::vector<double>& v);
  void vector(const Eigen::VectorXd& v);
  void vec3s(const std::vector<Eigen::Vector3d>& v);
  void matrix(const Eigen::MatrixXd& m);  // rows, columns, then the entries column by column

  // The archive with its checksum; the writer is spent afterwards.
  std::string finish();
  std::size_t size() const { return bytes_.size(); }

 private:
  std::string bytes_;
  bool finished_ = false;
  void raw(const void* p, std::size_t n);
};

class BinaryReader {
 public:
  // Checks magic, checksum (truncation, corruption), format version, kind and kind version
  // (which must be within [oldest_kind_version, kind_version]; by default exactly kind_version).
  BinaryReader(std::string bytes, const std::string& kind, std::uint32_t kind_version, std::uint32_t oldest_kind_version = 0);
  // The layout version the archive was written with.
  std::uint32_t kind_version() const { return kind_version_; }

  std::uint32_t u32();
  std::int64_t i64();
  double f64();
  bool boolean();
  std::string string();
  void section(const std::string& tag);  // throws unless the next mark is this tag
  Eigen::Vector3d vec3();
  std::vector<double> f64s();
  Eigen::VectorXd vector();
  std::vector<Eigen::Vector3d> vec3s();
  Eigen::MatrixXd matrix();
  // A count that must equal `expected` (sizes of the model the state is loaded into).
  void expect_count(const char* what, std::int64_t expected);
  // Throws unless the payload has been read completely.
  void finish() const;

 private:
  std::string bytes_;
  std::size_t pos_ = 0, end_ = 0;  // end_: start of the checksum
  std::uint32_t kind_version_ = 0;
  void raw(void* p, std::size_t n);
  std::size_t count(std::size_t item_bytes);
};

// Whole file as bytes; throws ArchiveError naming the file when it cannot be read.
std::string read_binary_file(const std::filesystem::path& path);

}  // namespace spifit::io
