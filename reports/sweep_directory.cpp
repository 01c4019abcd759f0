#include "reports/sweep_directory.hpp"

#include "forward/io/input_error.hpp"
#include "forward/io/text_file.hpp"

#include <nlohmann/json.hpp>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace spifit::reports {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

json read_summary(const fs::path& file) {
  try {
    return json::parse(io::read_text_file(file.string()));
  } catch (const json::exception& e) {
    throw io::InputError(file.string(), "", "", std::string("not JSON: ") + io::one_line(e.what(), 160));
  }
}

std::vector<std::string> strings(const json& j, const std::string& key, const fs::path& file) {
  const auto it = j.find(key);
  if (it == j.end() || !it->is_array())
    throw io::InputError(file.string(), key, "", "missing: the sweep is still running, or was written by an older spifit (run it again)");
  std::vector<std::string> out;
  for (const auto& v : *it) out.push_back(v.is_string() ? v.get<std::string>() : std::string());
  return out;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream ss(line);
  for (std::string c; std::getline(ss, c, ',');) cells.push_back(io::trim(c));
  return cells;
}

}  // namespace

bool is_sweep_directory(const fs::path& dir) {
  const fs::path file = dir / "summary.json";
  if (!fs::is_regular_file(file)) return false;
  try {
    const json j = json::parse(io::read_text_file(file.string()));
    return j.is_object() && j.value("kind", std::string()) == "sweep";
  } catch (const std::exception&) {
    return false;
  }
}

SweepReportSummary rerender_sweep_report(const fs::path& dir, bool plots) {
  const fs::path summary = dir / "summary.json", csv = dir / "sweep.csv";
  const json j = read_summary(summary);
  SweepTable t;
  t.inputs = strings(j, "inputs", summary);
  t.input_units = strings(j, "input_units", summary);
  t.metrics = strings(j, "metrics", summary);
  t.metric_units = strings(j, "metric_units", summary);
  const std::vector<std::string> messages = j.contains("messages") ? strings(j, "messages", summary) : std::vector<std::string>{};

  std::istringstream in(io::read_text_file(csv.string()));
  std::string line;
  std::getline(in, line);
  std::vector<std::string> expected = t.inputs;
  expected.insert(expected.end(), t.metrics.begin(), t.metrics.end());
  expected.push_back("wall_seconds");
  expected.push_back("ok");
  if (split(line) != expected) throw io::InputError(csv.string(), "line 1", line, "not the header the sweep's summary.json describes");
  for (int lineno = 2; std::getline(in, line); ++lineno) {
    if (io::trim(line).empty()) continue;
    const auto cells = split(line);
    if (cells.size() != expected.size())
      throw io::InputError(csv.string(), "line " + std::to_string(lineno), line, std::to_string(expected.size()) + " columns expected");
    std::vector<double> v;
    for (const auto& c : cells) {
      char* end = nullptr;
      errno = 0;
      const double x = std::strtod(c.c_str(), &end);
      if (c.empty() || *end != '\0') throw io::InputError(csv.string(), "line " + std::to_string(lineno), c, "not a number");
      v.push_back(x);
    }
    const auto mid = v.begin() + static_cast<std::ptrdiff_t>(t.inputs.size());
    const auto metrics_end = mid + static_cast<std::ptrdiff_t>(t.metrics.size());
    t.input_values.emplace_back(v.begin(), mid);
    t.metric_values.emplace_back(mid, metrics_end);
    t.wall_seconds.push_back(v[v.size() - 2]);
    t.ok.push_back(v.back() != 0.0);
  }
  return render_sweep_report(dir, j.value("sweep", dir.filename().string()), t, messages, plots);
}

}  // namespace spifit::reports
