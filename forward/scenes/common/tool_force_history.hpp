#pragma once
// The tool force of a run after every committed increment (a typed series of the results):
// where the tool was, the force BY the sheet ON the tool as the scene reports it (a half model
// mirrored to the whole sheet, a pie's real tool with its virtual copies), and how deep the tool
// sat in the sheet. Peaks keep their sign: the component of largest magnitude seen so far.
#include <Eigen/Core>

#include <optional>
#include <vector>

namespace spifit::io {
class BinaryWriter;
class BinaryReader;
}  // namespace spifit::io

namespace spifit::scene {

struct ToolForceSample {
  double travel = 0.0;  // mm along the tool path
  double time = 0.0;    // s (travel over the feed)
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // tool centre [mm]
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   // [N]
  double penetration = 0.0;          // deepest contact point [mm]
  double surface_penetration = 0.0;  // deepest point of the tool-side surface [mm]
  int iterations = 0;                // Newton iterations of the increment
};

class ToolForceHistory;
// The sample whose component k (0 x, 1 y, 2 z) is ToolForceHistory::peak()'s: the first of the
// largest magnitude; none while every sample's is zero.
std::optional<std::size_t> peak_sample(const ToolForceHistory& h, int k);
// The last sample (final_force()'s); none without samples.
std::optional<std::size_t> last_sample(const ToolForceHistory& h);

class ToolForceHistory {
 public:
  void add(const ToolForceSample& s);
  const std::vector<ToolForceSample>& samples() const { return samples_; }
  bool empty() const { return samples_.empty(); }
  const Eigen::Vector3d& peak() const { return peak_; }
  // The last sample's force (zero without samples).
  Eigen::Vector3d final_force() const { return samples_.empty() ? Eigen::Vector3d::Zero() : samples_.back().force; }
  double max_penetration() const { return max_penetration_; }
  double max_surface_penetration() const { return max_surface_penetration_; }
  // Bit-exact (checkpoints); load replays the samples into an empty history.
  void save(io::BinaryWriter& w) const;
  void load(io::BinaryReader& r);

 private:
  std::vector<ToolForceSample> samples_;
  Eigen::Vector3d peak_ = Eigen::Vector3d::Zero();
  double max_penetration_ = 0.0, max_surface_penetration_ = 0.0;
};

}  // namespace spifit::scene
