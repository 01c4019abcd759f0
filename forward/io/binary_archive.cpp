#include "forward/io/binary_archive.hpp"

#include <algorithm>
#include <bit>
#include <cstring>
#include <fstream>
#include <iterator>

namespace spifit::io {
namespace {

constexpr char kMagic[8] = {'S', 'P', 'I', 'F', 'I', 'T', 'A', 'R'};

// Fixed little-endian byte order whatever the host's.
void put_le(std::string& out, std::uint64_t v, int bytes) {
  for (int i = 0; i < bytes; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xffU));
}
std::uint64_t get_le(const unsigned char* p, int bytes) {
  std::uint64_t v = 0;
  for (int i = 0; i < bytes; ++i) v |= static_cast<std::uint64_t>(p[i]) << (8 * i);
  return v;
}

}  // namespace

std::uint64_t fnv1a64(std::string_view bytes, std::uint64_t seed) {
  std::uint64_t h = seed;
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 0x100000001b3ULL;
  }
  return h;
}

BinaryWriter::BinaryWriter(const std::string& kind, std::uint32_t kind_version) {
  bytes_.append(kMagic, sizeof kMagic);
  u32(kFormatVersion);
  string(kind);
  u32(kind_version);
}

void BinaryWriter::raw(const void* p, std::size_t n) {
  if (finished_) throw std::logic_error("BinaryWriter used after finish()");
  bytes_.append(static_cast<const char*>(p), n);
}

void BinaryWriter::u32(std::uint32_t v) {
  if (finished_) throw std::logic_error("BinaryWriter used after finish()");
  put_le(bytes_, v, 4);
}
void BinaryWriter::i64(std::int64_t v) {
  if (finished_) throw std::logic_error("BinaryWriter used after finish()");
  put_le(bytes_, static_cast<std::uint64_t>(v), 8);
}
void BinaryWriter::f64(double v) { i64(static_cast<std::int64_t>(std::bit_cast<std::uint64_t>(v))); }
void BinaryWriter::boolean(bool v) { u32(v ? 1U : 0U); }
void BinaryWriter::string(const std::string& s) {
  i64(static_cast<std::int64_t>(s.size()));
  raw(s.data(), s.size());
}
void BinaryWriter::section(const std::string& tag) { string("@" + tag); }
void BinaryWriter::vec3(const Eigen::Vector3d& v) {
  for (int i = 0; i < 3; ++i) f64(v(i));
}
void BinaryWriter::f64s(const std::vector<double>& v) {
  i64(static_cast<std::int64_t>(v.size()));
  for (double x : v) f64(x);
}
void BinaryWriter::vector(const Eigen::VectorXd& v) {
  i64(static_cast<std::int64_t>(v.size()));
  for (Eigen::Index i = 0; i < v.size(); ++i) f64(v(i));
}
void BinaryWriter::vec3s(const std::vector<Eigen::Vector3d>& v) {
  i64(static_cast<std::int64_t>(v.size()));
  for (const auto& x : v) vec3(x);
}

void BinaryWriter::matrix(const Eigen::MatrixXd& m) {
  i64(static_cast<std::int64_t>(m.rows()));
  i64(static_cast<std::int64_t>(m.cols()));
  for (Eigen::Index j = 0; j < m.cols(); ++j)
    for (Eigen::Index i = 0; i < m.rows(); ++i) f64(m(i, j));
}

std::string BinaryWriter::finish() {
  if (finished_) throw std::logic_error("BinaryWriter::finish() called twice");
  put_le(bytes_, fnv1a64(bytes_), 8);
  finished_ = true;
  return std::move(bytes_);
}

BinaryReader::BinaryReader(std::string bytes, const std::string& kind, std::uint32_t kind_version, std::uint32_t oldest_kind_version)
    : bytes_(std::move(bytes)) {
  if (oldest_kind_version == 0) oldest_kind_version = kind_version;
  if (bytes_.size() < sizeof kMagic || std::memcmp(bytes_.data(), kMagic, sizeof kMagic) != 0)
    throw ArchiveError("not a spifit state archive (no SPIFITAR header)");
  if (bytes_.size() < sizeof kMagic + 4 + 8 + 4 + 8) throw ArchiveError("truncated archive (" + std::to_string(bytes_.size()) + " bytes)");
  end_ = bytes_.size() - 8;
  const std::uint64_t stored = get_le(reinterpret_cast<const unsigned char*>(bytes_.data()) + end_, 8);
  if (stored != fnv1a64(std::string_view(bytes_).substr(0, end_)))
    throw ArchiveError("checksum mismatch: the archive is truncated or corrupted (" + std::to_string(bytes_.size()) + " bytes)");
  pos_ = sizeof kMagic;
  const std::uint32_t format = u32();
  if (format != BinaryWriter::kFormatVersion)
    throw ArchiveError("archive format version " + std::to_string(format) + ", this spifit reads version " +
                       std::to_string(BinaryWriter::kFormatVersion));
  const std::string k = string();
  if (k != kind) throw ArchiveError("holds a \"" + k + "\", expected a \"" + kind + "\"");
  const std::uint32_t v = u32();
  if (v < oldest_kind_version || v > kind_version)
    throw ArchiveError("\"" + kind + "\" layout version " + std::to_string(v) + ", this spifit reads version " +
                       (oldest_kind_version == kind_version ? std::to_string(kind_version)
                                                            : std::to_string(oldest_kind_version) + " to " + std::to_string(kind_version)));
  kind_version_ = v;
}

void BinaryReader::raw(void* p, std::size_t n) {
  if (n > end_ - pos_) throw ArchiveError("unexpected end of the archive at byte " + std::to_string(pos_));
  std::memcpy(p, bytes_.data() + pos_, n);
  pos_ += n;
}

std::uint32_t BinaryReader::u32() {
  unsigned char b[4];
  raw(b, 4);
  return static_cast<std::uint32_t>(get_le(b, 4));
}
std::int64_t BinaryReader::i64() {
  unsigned char b[8];
  raw(b, 8);
  return static_cast<std::int64_t>(get_le(b, 8));
}
double BinaryReader::f64() { return std::bit_cast<double>(static_cast<std::uint64_t>(i64())); }
bool BinaryReader::boolean() {
  const std::uint32_t v = u32();
  if (v > 1) throw ArchiveError("invalid boolean " + std::to_string(v) + " at byte " + std::to_string(pos_ - 4));
  return v == 1;
}

std::size_t BinaryReader::count(std::size_t item_bytes) {
  const std::int64_t n = i64();
  if (n < 0 || static_cast<std::uint64_t>(n) > (end_ - pos_) / std::max<std::size_t>(item_bytes, 1))
    throw ArchiveError("invalid count " + std::to_string(n) + " at byte " + std::to_string(pos_ - 8));
  return static_cast<std::size_t>(n);
}

std::string BinaryReader::string() {
  const std::size_t n = count(1);
  std::string s(n, '\0');
  raw(s.data(), n);
  return s;
}
void BinaryReader::section(const std::string& tag) {
  const std::size_t at = pos_;
  const std::string t = string();
  if (t != "@" + tag) throw ArchiveError("section \"" + tag + "\" expected at byte " + std::to_string(at) + ", found \"" + t + "\"");
}
Eigen::Vector3d BinaryReader::vec3() {
  Eigen::Vector3d v;
  for (int i = 0; i < 3; ++i) v(i) = f64();
  return v;
}
std::vector<double> BinaryReader::f64s() {
  std::vector<double> v(count(8));
  for (double& x : v) x = f64();
  return v;
}
Eigen::VectorXd BinaryReader::vector() {
  Eigen::VectorXd v(static_cast<Eigen::Index>(count(8)));
  for (Eigen::Index i = 0; i < v.size(); ++i) v(i) = f64();
  return v;
}
std::vector<Eigen::Vector3d> BinaryReader::vec3s() {
  std::vector<Eigen::Vector3d> v(count(24));
  for (auto& x : v) x = vec3();
  return v;
}

Eigen::MatrixXd BinaryReader::matrix() {
  const std::int64_t rows = i64();
  if (rows < 0 || rows > 2'000'000'000) throw ArchiveError("invalid matrix row count " + std::to_string(rows) + " at byte " + std::to_string(pos_ - 8));
  const std::size_t cols = count(8 * static_cast<std::size_t>(std::max<std::int64_t>(rows, 1)));
  Eigen::MatrixXd m(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(cols));
  for (Eigen::Index j = 0; j < m.cols(); ++j)
    for (Eigen::Index i = 0; i < m.rows(); ++i) m(i, j) = f64();
  return m;
}

void BinaryReader::expect_count(const char* what, std::int64_t expected) {
  const std::int64_t n = i64();
  if (n != expected)
    throw ArchiveError(std::string("state of ") + std::to_string(n) + " " + what + ", the model has " + std::to_string(expected));
}

void BinaryReader::finish() const {
  if (pos_ != end_) throw ArchiveError(std::to_string(end_ - pos_) + " unread bytes at the end of the archive");
}

std::string read_binary_file(const std::filesystem::path& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw ArchiveError("cannot open " + path.string());
  std::string bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  if (f.bad()) throw ArchiveError("cannot read " + path.string());
  return bytes;
}

}  // namespace spifit::io
