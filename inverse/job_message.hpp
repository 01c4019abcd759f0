#pragma once
// The bytes of a job or an answer (job_pool.hpp): numbers as their exact bits, strings with
// their length. Reading past the end throws std::runtime_error.
#include <cstdint>
#include <string>
#include <vector>

namespace spifit::inverse {

class MessageWriter {
 public:
  MessageWriter& number(double v);
  MessageWriter& integer(std::int64_t v);
  MessageWriter& text(const std::string& s);
  MessageWriter& numbers(const std::vector<double>& v);
  const std::string& bytes() const { return bytes_; }

 private:
  void raw(const void* p, std::size_t n) { bytes_.append(static_cast<const char*>(p), n); }
  std::string bytes_;
};

class MessageReader {
 public:
  explicit MessageReader(const std::string& bytes) : bytes_(&bytes) {}
  double number();
  std::int64_t integer();
  std::string text();
  std::vector<double> numbers();
  bool at_end() const { return pos_ == bytes_->size(); }

 private:
  void raw(void* p, std::size_t n);
  const std::string* bytes_;
  std::size_t pos_ = 0;
};

}  // namespace spifit::inverse
