#include "forward/scenes/common/run_checkpoint.hpp"

#include "forward/io/atomic_file.hpp"
#include "forward/io/binary_archive.hpp"
#include "forward/io/input_error.hpp"
#include "forward/io/text_file.hpp"
#include "forward/model/model_archive.hpp"
#include "forward/model/fe_model.hpp"

#include <nlohmann/json.hpp>

#include <system_error>
#include <utility>

namespace spifit::scene {
namespace {

constexpr char kKind[] = "fe-run-checkpoint";
// Bump when the layout below, the model's or an observer's state, or the meaning of the stored
// load factor changes.
// 2: the cone's section points; 3: the Newton assembly counters; 4: a "scheme" section in place of
// "newton_state": a flag, then the Newton state (implicit runs) or, new, an explicit run's options,
// mass, solver and MST state.
constexpr std::uint32_t kLayout = 4;

void save_log(io::BinaryWriter& w, const RunLog& log) {
  w.section("run_log");
  w.i64(log.increments);
  w.i64(log.marks_reached);
  w.f64s(log.mark_wall);
  w.f64(log.wall_seconds);
}

int load_count(io::BinaryReader& r, const char* what) {
  const std::int64_t v = r.i64();
  if (v < 0 || v > 2'000'000'000) throw io::ArchiveError(std::string("invalid ") + what + " " + std::to_string(v));
  return static_cast<int>(v);
}

RunLog load_log(io::BinaryReader& r) {
  r.section("run_log");
  RunLog log;
  log.increments = load_count(r, "increment count");
  log.marks_reached = load_count(r, "mark count");
  log.mark_wall = r.f64s();
  log.wall_seconds = r.f64();
  if (static_cast<int>(log.mark_wall.size()) != log.marks_reached) throw io::ArchiveError("inconsistent run log (marks and their wall times)");
  return log;
}

// Section "scheme": whether the run is explicit, then its dynamics, or the Newton solver's state.
void save_scheme(io::BinaryWriter& w, const solver::NewtonState* newton, const CheckpointPart* dynamics) {
  w.section("scheme");
  w.boolean(dynamics != nullptr);
  if (dynamics) dynamics->save(w);
  else solver::save_newton_state(w, *newton);
}

void load_scheme(io::BinaryReader& r, solver::NewtonState* newton, CheckpointPart* dynamics, int num_dofs, bool sensitivities) {
  r.section("scheme");
  const bool saved_explicit = r.boolean();
  if (saved_explicit && !dynamics) throw io::ArchiveError("written by an explicit run, this run is implicit");
  if (!saved_explicit && dynamics) throw io::ArchiveError("written by an implicit run, this run is explicit");
  if (dynamics) {
    dynamics->restore(r);
    return;
  }
  *newton = solver::load_newton_state(r, sensitivities);
  if (newton->last_increment.size() != 0 && newton->last_increment.size() != num_dofs)
    throw io::ArchiveError("Newton predictor of another model size");
}

[[noreturn]] void refuse(const std::filesystem::path& file, const std::string& why) {
  throw io::InputError(file.string(), "", "", "cannot resume: " + why);
}

const RunInput* scene_input(const std::vector<RunInput>& files) {
  for (const auto& f : files)
    if (f.role == "scene") return &f;
  return nullptr;
}

bool same_file(const std::string& a, const std::string& b) {
  std::error_code ec;
  return std::filesystem::weakly_canonical(a, ec) == std::filesystem::weakly_canonical(b, ec);
}

// "of scene A (kind K), not of scene B (kind L)" when the scene that started the run (kind, path)
// is another file than the resumed run's (a --resume into the directory of another scene); ""
// otherwise (also when either is unknown).
std::string other_scene(const std::string& kind, const std::string& path, const RunInputs& inputs) {
  const RunInput* mine = scene_input(inputs.files);
  if (!mine || path.empty() || (kind == inputs.kind && same_file(path, mine->path))) return "";
  return "of scene " + path + " (kind " + kind + "), not of scene " + mine->path + " (kind " + inputs.kind + ")";
}

constexpr char kSensitivitiesRole[] = "sensitivities";

const RunInput* sensitivities_of(const std::vector<RunInput>& files) {
  for (const auto& f : files)
    if (f.role == kSensitivitiesRole) return &f;
  return nullptr;
}

// The derivatives a checkpoint holds against those the resumed run asks for.
void check_sensitivities(const std::vector<RunInput>& stored, const std::vector<RunInput>& mine, const std::filesystem::path& file) {
  const RunInput* theirs = sensitivities_of(stored);
  const RunInput* ours = sensitivities_of(mine);
  const std::string afresh = ", or start the run afresh in a new output directory";
  if (theirs && !ours) refuse(file, "written by a run with sensitivities " + theirs->text + ": resume with --sensitivities " + theirs->text + afresh);
  if (!theirs && ours) refuse(file, "written by a run without sensitivities: resume without --sensitivities" + afresh);
  if (theirs && ours && theirs->text != ours->text)
    refuse(file, "written by a run with sensitivities " + theirs->text + ", not " + ours->text + ": resume with --sensitivities " +
                     theirs->text + afresh);
}

// The stored inputs against the resumed run's: the same kind and the same contents file by file.
void check_inputs(io::BinaryReader& r, const RunInputs& inputs, const std::filesystem::path& file) {
  r.section("inputs");
  (void)r.string();  // the version of spifit that wrote it (informative: another build with the same layout is accepted)
  const std::string kind = r.string();
  const int n = load_count(r, "input file count");
  std::vector<RunInput> stored(static_cast<std::size_t>(n));
  for (auto& f : stored) {
    f.role = r.string();
    f.path = r.string();
    f.text = r.string();
  }
  // A run of another kind: the directory of another scene, both named (a scene of the same kind
  // is compared by contents below, which names both too).
  const RunInput* theirs = scene_input(stored);
  if (kind != inputs.kind && theirs)
    if (const std::string why = other_scene(kind, theirs->path, inputs); !why.empty())
      refuse(file, "the checkpoint is " + why + ": resume with that scene, or run this one in another output directory");
  if (kind != inputs.kind) refuse(file, "written by a " + kind + " run, not a " + inputs.kind + " run");
  check_sensitivities(stored, inputs.files, file);
  if (n != static_cast<int>(inputs.files.size()))
    refuse(file, "written for a run with " + std::to_string(n) + " input files, this one has " + std::to_string(inputs.files.size()));
  for (std::size_t i = 0; i < stored.size(); ++i) {
    const RunInput& in = inputs.files[i];
    const std::string& role = stored[i].role;
    const std::string& path = stored[i].path;
    if (role != in.role) refuse(file, "written with a " + role + " where this run has a " + in.role);
    if (stored[i].text != in.text)
      refuse(file, "written with another " + in.role + ": the contents of " + in.path + " differ from those of " + path +
                       " when the run started (a copy is in the checkpoint); resume with that " + in.role +
                       ", or start the run afresh in a new output directory");
  }
}

// The kind and scene file of the run whose summary.json is in dir; empty when there is none.
std::pair<std::string, std::string> summary_scene(const std::filesystem::path& dir) {
  try {
    const auto j = nlohmann::json::parse(io::read_text_file((dir / "summary.json").string()));
    return {j.value("kind", ""), j.value("scene_file", "")};
  } catch (const std::exception&) {
    return {};
  }
}

}  // namespace

RunInputs read_run_inputs(const std::string& kind, const std::vector<std::pair<std::string, std::string>>& files) {
  RunInputs in;
  in.kind = kind;
  for (const auto& [role, path] : files)
    if (!path.empty()) in.files.push_back({role, path, io::read_text_file(path)});
  return in;
}

RunInput sensitivity_input(const std::vector<std::string>& names) {
  RunInput in{kSensitivitiesRole, "--sensitivities", ""};
  for (const std::string& n : names) in.text += (in.text.empty() ? "" : ",") + n;
  return in;
}

std::filesystem::path run_checkpoint_path(const io::OutputDirectory& out) { return out.path() / "checkpoint" / "state.bin"; }

std::size_t write_run_checkpoint(const io::OutputDirectory& out, const RunInputs& inputs, const model::FeModel& model,
                                 const solver::NewtonState* newton, const CheckpointPart* dynamics, const RunLog& log,
                                 const Observers& observers) {
  io::BinaryWriter w(kKind, kLayout);
  w.section("inputs");
  w.string(SPIFIT_VERSION);
  w.string(inputs.kind);
  w.i64(static_cast<std::int64_t>(inputs.files.size()));
  for (const auto& f : inputs.files) {
    w.string(f.role);
    w.string(f.path);
    w.string(f.text);
  }
  model::save_model_state(w, model);
  save_scheme(w, newton, dynamics);
  save_log(w, log);
  w.section("observers");
  w.i64(static_cast<std::int64_t>(observers.size()));
  for (const auto& o : observers) {
    w.string(o->name());
    o->save(w);
  }
  w.section("end");
  const std::string bytes = w.finish();
  io::write_file_atomic(run_checkpoint_path(out), bytes);  // .state.bin.tmp in DIR/checkpoint/, then renamed
  out.record();  // checkpoint/ in the manifest
  return bytes.size();
}

void read_run_checkpoint(const io::OutputDirectory& out, const RunInputs& inputs, model::FeModel* model, solver::NewtonState* newton,
                         CheckpointPart* dynamics, RunLog* log, const Observers& observers) {
  const std::filesystem::path file = run_checkpoint_path(out);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) {
    const auto [kind, scene] = summary_scene(out.path());
    if (const std::string why = other_scene(kind, scene, inputs); !why.empty())
      refuse(file, "no checkpoint, and the run in " + out.path().string() + " is " + why + ": run this one in another output directory");
    refuse(file, "no checkpoint in " + out.path().string() + " (written after every [output] checkpoint_every marks and checkpoint_increments increments)");
  }
  try {
    io::BinaryReader r(io::read_binary_file(file), kKind, kLayout);
    check_inputs(r, inputs, file);
    model::load_model_state(r, model);
    load_scheme(r, newton, dynamics, model->num_dofs(), model->sensitivity_count() > 0);
    *log = load_log(r);
    r.section("observers");
    r.expect_count("observers", static_cast<std::int64_t>(observers.size()));
    for (const auto& o : observers) {
      const std::string name = r.string();
      if (name != o->name()) throw io::ArchiveError("observer \"" + name + "\" in the checkpoint where the run has \"" + o->name() + "\"");
      o->restore(r);
    }
    r.section("end");
    r.finish();
  } catch (const io::ArchiveError& e) {
    refuse(file, e.what());
  }
}

}  // namespace spifit::scene
