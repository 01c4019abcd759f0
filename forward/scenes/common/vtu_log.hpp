#pragma once
// ParaView output of a run: DIR/vtu/STEM.pvd and its steps (mesh/vtu_writer.hpp) -- the
// initial state, every `every` increments (0: none between), and the final state unless the
// last increment wrote it already. Time = the tool's time along its path [s].
#include "forward/mesh/vtu_writer.hpp"
#include "forward/model/model_vtu.hpp"
#include "forward/scenes/common/run_files.hpp"
#include "forward/scenes/common/run_observer.hpp"

#include <memory>
#include <string>
#include <vector>

namespace spifit::scene {

class VtuLog : public RunObserver {
 public:
  VtuLog(const RunFiles& files, int every, const std::string& stem = "sheet");
  // A run with sensitivities: the displacement's derivatives with respect to these parameters (of
  // these values) in every step as well (model::vtu_frame).
  void set_sensitivities(std::vector<std::string> names, std::vector<double> values) {
    names_ = std::move(names);
    values_ = std::move(values);
  }
  int steps() const { return pvd_ ? pvd_->steps() : 0; }

  std::string name() const override { return "vtu_log"; }
  void at_start(const model::FeModel& model) override;
  void after_increment(const IncrementView& v) override;
  void at_end(const model::FeModel& model, double time) override;
  void save(io::BinaryWriter& w) const override;
  void restore(io::BinaryReader& r) override;

 private:
  const RunFiles& files_;
  std::string stem_;
  std::unique_ptr<mesh::PvdCollection> pvd_;
  void open();
  int every_ = 0;
  int increments_ = 0;
  std::vector<std::string> names_;
  std::vector<double> values_;
  mesh::VtuFrame frame(const model::FeModel& model) const { return model::vtu_frame(model, names_, values_); }
};

}  // namespace spifit::scene
