#include "inverse/job_message.hpp"

#include <cstring>
#include <stdexcept>

namespace spifit::inverse {

MessageWriter& MessageWriter::number(double v) {
  raw(&v, sizeof v);
  return *this;
}
MessageWriter& MessageWriter::integer(std::int64_t v) {
  raw(&v, sizeof v);
  return *this;
}
MessageWriter& MessageWriter::text(const std::string& s) {
  integer(static_cast<std::int64_t>(s.size()));
  raw(s.data(), s.size());
  return *this;
}
MessageWriter& MessageWriter::numbers(const std::vector<double>& v) {
  integer(static_cast<std::int64_t>(v.size()));
  if (!v.empty()) raw(v.data(), v.size() * sizeof(double));
  return *this;
}

void MessageReader::raw(void* p, std::size_t n) {
  if (n > bytes_->size() - pos_) throw std::runtime_error("job message: cut short");
  std::memcpy(p, bytes_->data() + pos_, n);
  pos_ += n;
}
double MessageReader::number() {
  double v = 0.0;
  raw(&v, sizeof v);
  return v;
}
std::int64_t MessageReader::integer() {
  std::int64_t v = 0;
  raw(&v, sizeof v);
  return v;
}
std::string MessageReader::text() {
  const std::int64_t n = integer();
  if (n < 0 || static_cast<std::size_t>(n) > bytes_->size() - pos_) throw std::runtime_error("job message: bad text length");
  std::string s(bytes_->data() + pos_, static_cast<std::size_t>(n));
  pos_ += static_cast<std::size_t>(n);
  return s;
}
std::vector<double> MessageReader::numbers() {
  const std::int64_t n = integer();
  if (n < 0 || static_cast<std::size_t>(n) > (bytes_->size() - pos_) / sizeof(double)) throw std::runtime_error("job message: bad array length");
  std::vector<double> v(static_cast<std::size_t>(n));
  if (n > 0) raw(v.data(), v.size() * sizeof(double));
  return v;
}

}  // namespace spifit::inverse
