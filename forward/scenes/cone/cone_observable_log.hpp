#pragma once
// The shape, stage and element observables of a cone run (docs/design/cone.md) and their files:
//  - after each completed contour: sections/section_s<stage>_c<contour>.csv (cone_sections.hpp)
//    and sections/elongation_s<stage>_c<contour>.csv, and a row of sections.csv (wall-thickness
//    plateau vs the sine law, thinnest node, largest radial elongation, centre depth);
//  - at the end of each stage (the end of its retract; thesis Fig. 8.16): a row of stages.csv
//    with the height and depth of the part centre (the axis node's mid-surface);
//  - after every increment, with [output] history_element: a row of history.csv
//    (element_history.hpp; a shell model's).
// Sections see the sheet through its family's mid-surface (ElementFamily::mid_surface): a
// shell's nodes and directors, a solid's node columns.
#include "forward/element/thickness_rule.hpp"
#include "forward/io/series.hpp"
#include "forward/scenes/common/run_files.hpp"
#include "forward/scenes/common/run_observer.hpp"
#include "forward/scenes/cone/cone_observables.hpp"
#include "forward/scenes/cone/cone_sections.hpp"

#include <nlohmann/json.hpp>

#include <vector>

namespace spifit::mesh {
struct Mesh;
}  // namespace spifit::mesh

namespace spifit::model {
class FeModel;
struct MidSurface;
}  // namespace spifit::model

namespace spifit::scene {

struct ConeScene;

// Travelled distance at the end of each stage's path (the end of its retract; the path's end
// for the last stage), stage 1 first.
std::vector<double> stage_end_distances(const toolpath::ConePath& path);

class ConeObservableLog : public RunObserver {
 public:
  // The scene, model, the sheet's mid-surface mesh, track and files must outlive the log; the
  // mid-surface mesh gives the section line, the part centre and the history element
  // (std::invalid_argument for a history element in a model of another family than the shell).
  ConeObservableLog(const ConeScene& scene, const model::FeModel& model, const mesh::Mesh& mid_surface, const ConeTrack& track,
                    const RunFiles& files);

  // Per completed contour (sections.csv), per stage (stages.csv), per increment (history.csv).
  const io::Series& sections() const { return section_rows_; }
  const io::Series& stages() const { return stage_rows_; }
  const io::Series& history() const { return history_rows_; }
  // The section after each completed contour, in path order (what sections/ holds).
  const std::vector<ConeSection>& profiles() const { return profiles_; }
  // For summary.json: the history element, the last section summary and the stages.
  nlohmann::json summary() const;
  int history_element() const { return history_element_; }  // -1 without [output] history_element
  // A run with sensitivities: d(centre_depth)/dp at the end of each stage so far, as stages(); else empty.
  const std::vector<Eigen::RowVectorXd>& centre_depth_sensitivities() const { return depth_sensitivities_; }

  std::string name() const override { return "cone_observables"; }
  void after_increment(const IncrementView& v) override;
  void at_mark(const Mark& m, const IncrementView& v) override;
  // sections.csv, stages.csv and history.csv at marks and at the end, or when a stage has ended
  // since the last write (history.csv has one row per increment: rewriting it every increment
  // would cost O(n^2)).
  void write(WriteReason reason) override;
  void save(io::BinaryWriter& w) const override;
  void restore(io::BinaryReader& r) override;

 private:
  // The section line's nodes and the part centre's height on the sheet's mid-surface.
  std::vector<SectionNode> section_nodes(const model::MidSurface& mid) const;
  double centre_z(const model::MidSurface& mid) const;

  const ConeScene& scene_;
  const model::FeModel& model_;
  const mesh::Mesh& mid_surface_;
  const ConeTrack& track_;
  const RunFiles& files_;
  std::vector<int> line_;   // the section's nodes from the axis outwards
  int centre_node_ = -1;    // the axis node (of the mid-surface mesh)
  std::vector<double> stage_ends_;
  int history_element_ = -1;
  element::ThicknessRule rule_;
  io::Series section_rows_, stage_rows_, history_rows_;
  std::vector<ConeSection> profiles_;
  std::vector<Eigen::RowVectorXd> depth_sensitivities_;
  void add_section_sensitivities(const model::MidSurface& mid, ConeSection* section) const;
  std::size_t stages_written_ = 0;
};

}  // namespace spifit::scene
