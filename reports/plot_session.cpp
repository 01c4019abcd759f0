#include "reports/plot_session.hpp"

#include <utility>

namespace spifit::reports {

PlotSession::PlotSession(std::filesystem::path gnuplot, std::filesystem::path plots_dir)
    : gnuplot_(std::move(gnuplot)), plots_dir_(std::move(plots_dir)) {}

std::filesystem::path PlotSession::render(const PlotSpec& spec) {
  if (disabled_) return {};
  const auto r = render_plot(gnuplot_, plots_dir_, spec);
  if (r.ok) {
    images_.push_back(r.file);
    return r.file;
  }
  warnings_.push_back(r.message);
  if (++failures_ >= 2 && images_.empty()) {
    disabled_ = true;
    warnings_.push_back("gnuplot fails; the remaining plots were skipped");
  }
  return {};
}

}  // namespace spifit::reports
