#pragma once
// The shape, stage and element observables of a cone run (SPEC §4; docs/cone-scene.md) and
// their files, next to the force log of cone_scene_run.cpp:
//  - after each completed contour: sections/section_s<stage>_c<contour>.csv (cone_sections.hpp)
//    and sections/elongation_s<stage>_c<contour>.csv, and a row of sections.csv (wall-thickness
//    plateau vs the sine law, thinnest node, largest radial elongation, centre depth);
//  - at the end of each stage (the end of its retract; thesis Fig. 8.16): a row of stages.csv
//    with the height and depth of the part centre (the axis node's mid-surface);
//  - after every increment, with [output] history_element: a row of history.csv
//    (element_history.hpp).
#include "forward/element/thickness_rule.hpp"
#include "forward/io/output_directory.hpp"
#include "forward/scenes/cone_observables.hpp"
#include "forward/scenes/cone_sections.hpp"

#include <nlohmann/json.hpp>

#include <vector>

namespace spifit::model {
class ShellModel;
}

namespace spifit::scene {

struct ConeScene;
struct ConeRunLog;

// Travelled distance at the end of each stage's path (the end of its retract; the path's end
// for the last stage), stage 1 first.
std::vector<double> stage_end_distances(const toolpath::ConePath& path);

class ConeObservableLog {
 public:
  // Creates DIR/sections/. The model, track and directory must outlive the log.
  ConeObservableLog(const ConeScene& scene, const model::ShellModel& model, const ConeTrack& track, const io::OutputDirectory& out);

  // After a committed increment at travelled distance `travel` (load factor lambda).
  void after_increment(double travel, double lambda);
  // After `span` is completed (the first increment past its end).
  void after_contour(const ContourSpan& span);
  // Rewrites sections.csv, stages.csv and history.csv when `now` (completed contours, end of
  // run) or when a stage has ended since the last write; otherwise does nothing (history.csv
  // has one row per increment: rewriting it every increment would cost O(n^2)).
  void write(bool now);
  // For summary.json: the history element, the last section summary and the stages.
  nlohmann::json summary() const;
  int history_element() const { return history_element_; }  // -1 without [output] history_element

  // Checkpoints (cone_checkpoint.hpp): the rows so far go into log->tables ("sections",
  // "stages", "history"); restore() continues an empty log from them.
  void save(ConeRunLog* log) const;
  void restore(const ConeRunLog& log);

 private:
  using Rows = std::vector<std::vector<double>>;
  std::vector<SectionNode> section_nodes() const;
  double centre_z() const;

  const ConeScene& scene_;
  const model::ShellModel& model_;
  const io::OutputDirectory& out_;
  std::vector<int> line_;   // the section's nodes from the axis outwards
  int centre_node_ = -1;    // the axis node
  std::vector<double> stage_ends_;
  int history_element_ = -1;
  element::ThicknessRule rule_;
  Rows section_rows_, stage_rows_, history_rows_;  // sections.csv, stages.csv, history.csv
  std::size_t stages_written_ = 0;
};

}  // namespace spifit::scene
