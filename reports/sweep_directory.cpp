#include "reports/sweep_directory.hpp"

#include "forward/io/input_error.hpp"
#include "forward/io/text_file.hpp"
#include "reports/output_table.hpp"

#include <nlohmann/json.hpp>

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

  // sweep.csv: the inputs, the metrics, wall_seconds and ok, as summary.json describes them.
  OutputTable csv_table;
  std::string why;
  if (!read_output_table(csv, &csv_table, &why)) throw io::InputError(csv.string(), "", "", why);
  std::vector<std::string> expected = t.inputs;
  expected.insert(expected.end(), t.metrics.begin(), t.metrics.end());
  expected.push_back("wall_seconds");
  expected.push_back("ok");
  if (csv_table.names != expected) throw io::InputError(csv.string(), "line 1", "", "not the columns the sweep's summary.json describes");
  auto column = [&](const std::string& name) { return csv_table.column(name); };
  std::vector<std::vector<double>> inputs, metrics;
  for (const auto& n : t.inputs) inputs.push_back(column(n));
  for (const auto& n : t.metrics) metrics.push_back(column(n));
  t.wall_seconds = column("wall_seconds");
  for (double ok : column("ok")) t.ok.push_back(ok != 0.0);
  for (std::size_t i = 0; i < csv_table.rows(); ++i) {
    t.input_values.emplace_back();
    t.metric_values.emplace_back();
    for (const auto& c : inputs) t.input_values.back().push_back(c[i]);
    for (const auto& c : metrics) t.metric_values.back().push_back(c[i]);
  }
  return render_sweep_report(dir, j.value("sweep", dir.filename().string()), t, messages, plots);
}

}  // namespace spifit::reports
