#pragma once
// The contour means of a cone run (thesis §8.3, footnote 8): the mean force over the central
// third of each completed contour (by travel), from the tool force history, as DIR/contours.csv
// (rewritten with force.csv) and a progress line per completed contour.
#include "forward/scenes/common/force_log.hpp"
#include "forward/scenes/common/run_files.hpp"
#include "forward/scenes/common/run_observer.hpp"
#include "forward/scenes/cone/cone_observables.hpp"

#include <string>
#include <vector>

namespace spifit::scene {

// The force samples of a history with their polar components at the tool centre's angle.
std::vector<ForceSample> polar_samples(const ToolForceHistory& history);

class ConeContourLog : public RunObserver {
 public:
  ConeContourLog(std::string scene, const ConeTrack& track, const ForceLog& force, const RunFiles& files);
  std::vector<ContourMean> means() const { return contour_means(track_, polar_samples(force_.history()), contours_); }

  std::string name() const override { return "cone_contours"; }
  void after_increment(const IncrementView& v) override { (void)v; }
  void at_mark(const Mark& m, const IncrementView& v) override;
  void write(WriteReason reason) override;
  void save(io::BinaryWriter& w) const override;
  void restore(io::BinaryReader& r) override;

 private:
  std::string scene_;
  const ConeTrack& track_;
  const ForceLog& force_;
  const RunFiles& files_;
  int contours_ = 0;  // completed
};

}  // namespace spifit::scene
