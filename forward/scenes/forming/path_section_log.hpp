#pragma once
// Sections of a forming run at its named path points (forming_scene.hpp [output] sections): the
// mid-surface of the nodes on the line y = 0 of the initial sheet, sorted by x, with their
// thickness, written as DIR/sections/section_<P>.csv when the tool reaches point P.
#include "forward/scenes/common/run_files.hpp"
#include "forward/scenes/common/run_observer.hpp"
#include "forward/scenes/forming/forming_result.hpp"

#include <string>
#include <vector>

namespace spifit::scene {

class PathSectionLog : public RunObserver {
 public:
  // points: the names of the path points to take sections at; scene: the scene's name (files);
  // sensitivities: the parameters of a run with sensitivities (their derivatives are in the
  // sections and in checkpoints), 0 otherwise.
  PathSectionLog(std::vector<std::string> points, std::string scene, const RunFiles& files, int sensitivities = 0);
  const std::vector<PathSection>& sections() const { return sections_; }

  std::string name() const override { return "path_sections"; }
  void after_increment(const IncrementView& v) override { (void)v; }
  void at_mark(const Mark& m, const IncrementView& v) override;
  void save(io::BinaryWriter& w) const override;
  void restore(io::BinaryReader& r) override;

 private:
  std::vector<std::string> points_;
  std::string scene_;
  const RunFiles& files_;
  int sensitivities_ = 0;
  std::vector<PathSection> sections_;
  static io::Series empty_section();
  void write_file(const PathSection& s) const;
};

}  // namespace spifit::scene
