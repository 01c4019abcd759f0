#pragma once
// The plots of one report, rendered in turn (render_plot, plot.hpp): keeps the images written
// and, in order, the warnings of the plots that failed. A gnuplot that cannot run at all fails
// every plot, so after two failures without any success the remaining plots are skipped.
#include "reports/plot.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace spifit::reports {

class PlotSession {
 public:
  PlotSession(std::filesystem::path gnuplot, std::filesystem::path plots_dir);

  // The image written (plots_dir/STEM.svg), or an empty path: failed or skipped.
  std::filesystem::path render(const PlotSpec& spec);

  const std::vector<std::filesystem::path>& images() const { return images_; }
  const std::vector<std::string>& warnings() const { return warnings_; }

 private:
  std::filesystem::path gnuplot_, plots_dir_;
  std::vector<std::filesystem::path> images_;
  std::vector<std::string> warnings_;
  int failures_ = 0;
  bool disabled_ = false;
};

}  // namespace spifit::reports
