#include "forward/scenes/benchmark/shell_benchmark_kind.hpp"

#include "forward/scenes/benchmark/shell_benchmark_inputs.hpp"
#include "forward/scenes/benchmark/shell_benchmark_scene.hpp"

namespace spifit::scene {
namespace {

// A benchmark brings its own material and has no named inputs.
class ShellBenchmarkSceneFile final : public Scene {
 public:
  explicit ShellBenchmarkSceneFile(ShellBenchmarkScene s) : data_(std::move(s)) {}
  const std::string& kind() const override { return kind_; }
  const std::string& name() const override { return data_.name; }
  const std::string& file() const override { return data_.file; }
  std::vector<std::string> input_files() const override { return {data_.file}; }
  std::unique_ptr<Scene> clone() const override { return std::make_unique<ShellBenchmarkSceneFile>(*this); }
  std::unique_ptr<SceneResult> run(const RunFiles& files, const RunControl& control) const override {
    return std::make_unique<ShellBenchmarkResult>(run_shell_benchmark_scene(data_, files, control));
  }
  const material::MaterialCard* card() const override { return nullptr; }
  material::MaterialCard* card() override { return nullptr; }

 protected:
  double own_input(const std::string& name) const override { throw std::invalid_argument("unknown input " + name); }
  std::string set_own_input(const std::string& name, double) override { throw std::invalid_argument("unknown input " + name); }
  bool has_own_input(const std::string&) const override { return false; }

 private:
  std::string kind_ = "shell_benchmark";
  ShellBenchmarkScene data_;
};

}  // namespace

SceneKind shell_benchmark_kind() {
  SceneKind k;
  k.name = "shell_benchmark";
  k.family = "shell_benchmark";
  k.doc = "an element benchmark (patch tests, Scordelis-Lo, hemisphere, twisted beam, roll-up, limit moment) against its reference";
  k.read = [](const std::string& file) -> std::unique_ptr<Scene> {
    return std::make_unique<ShellBenchmarkSceneFile>(read_shell_benchmark_scene(file));
  };
  k.inputs = shell_benchmark_inputs().infos();
  k.observables = {{"value", "", "the benchmark's quantity (summary.json value)", Observable::Needs::nothing, false,
                    [](const SceneResult& r, const ObservableOptions&) { return dynamic_cast<const ShellBenchmarkResult&>(r).value; }},
                   {"relative_error", "", "value / reference - 1", Observable::Needs::nothing, false,
                    [](const SceneResult& r, const ObservableOptions&) {
                      const auto& b = dynamic_cast<const ShellBenchmarkResult&>(r);
                      return b.value / b.reference - 1.0;
                    }}};
  return k;
}

}  // namespace spifit::scene
