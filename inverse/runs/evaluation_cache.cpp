#include "inverse/runs/evaluation_cache.hpp"

#include "forward/io/input_error.hpp"
#include "forward/io/text_file.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstdio>

namespace spifit::inverse {

namespace fs = std::filesystem;
using nlohmann::json;

EvaluationCache::EvaluationCache(const fs::path& file, const std::string& signature, bool resume) {
  if (resume) {
    std::ifstream in(file);
    if (!in) throw io::InputError(file.string(), "", "", "no evaluations to resume from (the fit did not start here, or not with FE experiments)");
    std::string line;
    std::getline(in, line);
    json head;
    try {
      head = json::parse(line);
    } catch (const json::exception&) {
    }
    if (!head.is_object() || head.value("signature", "") != signature)
      throw io::InputError(file.string(), "signature", head.is_object() ? head.value("signature", "") : "",
                           "the fit file, its card, scenes or data changed since these evaluations (now " + signature + "): start afresh with --force");
    while (std::getline(in, line)) {
      try {
        const json j = json::parse(line);
        Entry e{j.at("ok").get<bool>(), j.at("residuals").get<std::vector<double>>()};
        entries_[j.at("experiment").get<std::string>() + " " + j.at("point").get<std::string>()] = std::move(e);
        ++loaded_;
      } catch (const json::exception&) {
        // The last line of a killed fit may be torn: it is evaluated again.
      }
    }
    out_.open(file, std::ios::app);
  } else {
    fs::create_directories(file.parent_path());
    out_.open(file, std::ios::trunc);
    out_ << json{{"signature", signature}}.dump() << "\n" << std::flush;
  }
  if (!out_) throw io::InputError(file.string(), "", "", "cannot write");
}

std::optional<EvaluationCache::Entry> EvaluationCache::find(const std::string& experiment, const std::string& point) const {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = entries_.find(experiment + " " + point);
  if (it == entries_.end()) return std::nullopt;
  return it->second;
}

void EvaluationCache::add(const std::string& experiment, const std::string& point, const Entry& e) {
  std::string values;
  char buf[32];
  for (double v : e.residuals) {
    std::snprintf(buf, sizeof buf, "%.17g", v);
    if (!values.empty()) values += ',';
    values += buf;
  }
  std::lock_guard<std::mutex> lock(mutex_);
  if (!entries_.emplace(experiment + " " + point, e).second) return;
  out_ << "{\"experiment\":" << json(experiment).dump() << ",\"point\":" << json(point).dump() << ",\"ok\":" << (e.ok ? "true" : "false")
       << ",\"residuals\":[" << values << "]}\n"
       << std::flush;
}

std::string files_signature(const std::vector<std::string>& files) {
  std::uint64_t h = 1469598103934665603ULL;
  auto mix = [&h](const std::string& s) {
    for (unsigned char c : s) {
      h ^= c;
      h *= 1099511628211ULL;
    }
    h ^= 0xff;
    h *= 1099511628211ULL;
  };
  for (const auto& f : files) mix(io::read_text_file(f));
  char buf[24];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

}  // namespace spifit::inverse
