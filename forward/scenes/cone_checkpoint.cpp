#include "forward/scenes/cone_checkpoint.hpp"

#include "forward/io/atomic_file.hpp"
#include "forward/io/binary_archive.hpp"
#include "forward/io/input_error.hpp"
#include "forward/io/text_file.hpp"
#include "forward/model/shell_model.hpp"

#include <cstdio>
#include <system_error>

namespace spifit::scene {
namespace {

constexpr char kKind[] = "cone-checkpoint";
// Bump when the layout below or the meaning of the stored load factor changes (2: pie moves
// shortened by ConeLoadMap, so a load factor of layout 1 is another point of the path; 3: the
// model's external work and the contact's frictional dissipation, ModelEnergies; 4: force rows
// with surface_penetration and the run's largest; 5: the solver's predictor carries the
// rotations of framed nodes in their nodal frames, ShellModel::use_nodal_rotation_frames; 6: the
// solver's stabilisation state, NewtonState). Layout 5 is still read: it differs only by the
// stabilisation state, absent there (off).
constexpr std::uint32_t kLayout = 6;
constexpr std::uint32_t kOldestLayout = 5;

void save_rows(io::BinaryWriter& w, const std::vector<std::vector<double>>& rows) {
  w.i64(static_cast<std::int64_t>(rows.size()));
  for (const auto& row : rows) w.f64s(row);
}

std::vector<std::vector<double>> load_rows(io::BinaryReader& r) {
  const std::int64_t n = r.i64();
  if (n < 0 || n > 1'000'000'000) throw io::ArchiveError("invalid row count " + std::to_string(n));
  std::vector<std::vector<double>> rows;
  rows.reserve(static_cast<std::size_t>(std::min<std::int64_t>(n, 1'000'000)));
  for (std::int64_t i = 0; i < n; ++i) rows.push_back(r.f64s());
  return rows;
}

void save_log(io::BinaryWriter& w, const ConeRunLog& log) {
  w.section("run_log");
  save_rows(w, log.force_rows);
  w.i64(static_cast<std::int64_t>(log.samples.size()));
  for (const auto& s : log.samples) {
    w.f64(s.s);
    w.vec3(s.force);
    w.vec3(s.polar);
  }
  w.vec3(log.peak);
  w.vec3(log.peak_polar);
  w.i64(log.increments);
  w.i64(log.contours_done);
  w.f64(log.max_penetration);
  w.f64(log.max_surface_penetration);
  w.f64s(log.contour_wall);
  w.f64(log.wall_seconds);
  w.i64(static_cast<std::int64_t>(log.vtu_steps.size()));
  for (const auto& [t, f] : log.vtu_steps) {
    w.f64(t);
    w.string(f);
  }
  w.i64(static_cast<std::int64_t>(log.tables.size()));
  for (const auto& [name, rows] : log.tables) {
    w.string(name);
    save_rows(w, rows);
  }
}

int load_count(io::BinaryReader& r, const char* what) {
  const std::int64_t v = r.i64();
  if (v < 0 || v > 2'000'000'000) throw io::ArchiveError(std::string("invalid ") + what + " " + std::to_string(v));
  return static_cast<int>(v);
}

ConeRunLog load_log(io::BinaryReader& r) {
  r.section("run_log");
  ConeRunLog log;
  log.force_rows = load_rows(r);
  const int samples = load_count(r, "sample count");
  log.samples.resize(static_cast<std::size_t>(samples));
  for (auto& s : log.samples) {
    s.s = r.f64();
    s.force = r.vec3();
    s.polar = r.vec3();
  }
  log.peak = r.vec3();
  log.peak_polar = r.vec3();
  log.increments = load_count(r, "increment count");
  log.contours_done = load_count(r, "contour count");
  log.max_penetration = r.f64();
  log.max_surface_penetration = r.f64();
  log.contour_wall = r.f64s();
  log.wall_seconds = r.f64();
  const int steps = load_count(r, "VTU step count");
  for (int i = 0; i < steps; ++i) {
    const double t = r.f64();
    log.vtu_steps.emplace_back(t, r.string());
  }
  const int tables = load_count(r, "table count");
  for (int i = 0; i < tables; ++i) {
    std::string name = r.string();
    log.tables[name] = load_rows(r);
  }
  if (log.force_rows.size() != log.samples.size() || static_cast<int>(log.force_rows.size()) != log.increments ||
      static_cast<int>(log.contour_wall.size()) != log.contours_done)
    throw io::ArchiveError("inconsistent run log (rows, samples, increments or contours)");
  return log;
}

[[noreturn]] void refuse(const std::filesystem::path& file, const std::string& why) {
  throw io::InputError(file.string(), "", "", "cannot resume: " + why);
}

}  // namespace

ConeInputs read_cone_inputs(const ConeScene& scene) {
  ConeInputs in;
  in.scene_file = scene.file;
  in.scene_text = io::read_text_file(scene.file);
  in.card_file = scene.card.file;
  if (!scene.card.file.empty()) in.card_text = io::read_text_file(scene.card.file);
  return in;
}

std::filesystem::path cone_checkpoint_path(const io::OutputDirectory& out) { return out.path() / "checkpoint" / "state.bin"; }

std::size_t write_cone_checkpoint(const io::OutputDirectory& out, const ConeInputs& inputs, const model::ShellModel& model,
                                  const solver::NewtonState& newton, const ConeRunLog& log) {
  io::BinaryWriter w(kKind, kLayout);
  w.section("inputs");
  w.string(SPIFIT_VERSION);
  w.string(inputs.scene_file);
  w.string(inputs.scene_text);
  w.string(inputs.card_file);
  w.string(inputs.card_text);
  model.save_state(w);
  solver::save_newton_state(w, newton);
  save_log(w, log);
  w.section("end");
  const std::string bytes = w.finish();
  io::write_file_atomic(cone_checkpoint_path(out), bytes);  // .state.bin.tmp in DIR/checkpoint/, then renamed
  return bytes.size();
}

void read_cone_checkpoint(const io::OutputDirectory& out, const ConeInputs& inputs, model::ShellModel* model,
                          solver::NewtonState* newton, ConeRunLog* log) {
  const std::filesystem::path file = cone_checkpoint_path(out);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec))
    refuse(file, "no checkpoint in " + out.path().string() + " (written after every [output] checkpoint_every completed contours)");
  try {
    io::BinaryReader r(io::read_binary_file(file), kKind, kLayout, kOldestLayout);
    r.section("inputs");
    const std::string version = r.string();
    const std::string scene_file = r.string(), scene_text = r.string();
    const std::string card_file = r.string(), card_text = r.string();
    if (scene_text != inputs.scene_text)
      refuse(file, "written for another scene: the contents of " + inputs.scene_file + " differ from those of the scene that started the run (" +
                       scene_file + ", a copy is in the checkpoint); resume with that scene, or start afresh with --force");
    if (card_text != inputs.card_text)
      refuse(file, "written with another material card: the contents of " + inputs.card_file + " differ from those of " + card_file +
                       " when the run started; start afresh with --force");
    (void)version;  // informative (a checkpoint of another build with the same layout is accepted)
    model->load_state(r);
    *newton = solver::load_newton_state(r, r.kind_version() >= 6);
    if (newton->last_increment.size() != 0 && newton->last_increment.size() != model->num_dofs())
      throw io::ArchiveError("Newton predictor of another model size");
    *log = load_log(r);
    r.section("end");
    r.finish();
  } catch (const io::ArchiveError& e) {
    refuse(file, e.what());
  }
}

}  // namespace spifit::scene
