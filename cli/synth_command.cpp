// `spifit synth`: a SYNTHETIC measurement from a scene (inverse/experiments/synthetic.hpp).
#include "cli/commands.hpp"

#include "cli/cli_errors.hpp"
#include "forward/io/input_error.hpp"
#include "forward/scenes/material_point/material_point_file.hpp"
#include "forward/scenes/scene_registry.hpp"
#include "inverse/experiments/synthetic.hpp"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

namespace spifit::cli {

namespace {

// --set NAME=VALUE on a scene: io::InputError naming --set and the text when the name is not an
// input of the scene or the value is not one it can run with.
void set_scene_input(scene::Scene& sc, const std::string& assignment) {
  const std::size_t eq = assignment.find('=');
  if (eq == std::string::npos) throw io::InputError("", "--set", assignment, "expected NAME=VALUE");
  const std::string name = assignment.substr(0, eq), text = assignment.substr(eq + 1);
  double v = 0.0;
  try {
    std::size_t used = 0;
    v = std::stod(text, &used);
    if (used != text.size()) throw std::invalid_argument(text);
  } catch (const std::exception&) {
    throw io::InputError("", "--set", assignment, "the value is not a number");
  }
  std::string why;
  try {
    why = sc.set_input(name, v);
  } catch (const std::invalid_argument& e) {
    why = e.what();
  }
  if (!why.empty()) throw io::InputError(sc.file(), "--set", assignment, why);
}

}  // namespace

void add_synth_command(CLI::App& app, const GlobalOptions& g, int& exit_code, const std::string& command_line) {
  struct Opts { std::string scene, out, material, section, contour_means; std::vector<std::string> set; inverse::SyntheticOptions syn; bool force = false; };
  auto o = std::make_shared<Opts>();
  auto* cmd = app.add_subcommand("synth", "Write a SYNTHETIC measurement (twin experiment): a scene's curve with seeded noise");
  cmd->add_option("SCENE", o->scene, "scene file (TOML): a material point, or an FE scene with a tool")->required();
  cmd->add_option("--out", o->out, "CSV file to write")->required();
  cmd->add_option("--material", o->material, "generating card (default: the scene's)");
  cmd->add_option("--section", o->section, "a forming scene's section y = 0 at this path point instead of the tool force (x: x or x0; y: z or thickness)");
  cmd->add_option("--contour-means", o->contour_means, "a cone's central-third contour means of this component or ratio (fr, ftheta, fz, fx, fy, ftheta_over_fz, fr_over_fz) against the contour");
  cmd->add_option("--set", o->set, "NAME=VALUE: a named input of an FE scene for this run (e.g. contact.friction=0.05); repeatable");
  cmd->add_option("--x", o->syn.x, "abscissa column: strain, cumulative_strain, increment (material point; default strain); depth, travel, time (FE; default depth)");
  cmd->add_option("--y", o->syn.y, "response column: stress, eps_ww, eps_zz, ... (material point; default stress); fx, fy, fz, fr, ftheta (FE; default fz)");
  cmd->add_option("--noise", o->syn.noise, "standard deviation of the Gaussian noise on y (units of y)");
  cmd->add_option("--seed", o->syn.seed, "random seed");
  cmd->add_option("--every", o->syn.every, "keep every k-th increment");
  cmd->add_flag("--force", o->force, "overwrite an existing file");
  cmd->callback([o, &g, &exit_code, command_line, cmd] {
    const std::string kind = scene::scene_kind_of_file(o->scene);
    const scene::SceneKind* k = scene::find_scene_kind(kind);
    if (!k) (void)scene::read_scene(o->scene);  // names the unknown kind and the known ones
    if (std::filesystem::exists(o->out) && !o->force) throw io::InputError("", "--out", o->out, "file exists; pass --force to overwrite");
    o->syn.command = command_line;
    const bool fe = !k->jets;
    if (fe) {
      if (cmd->count("--x") == 0) o->syn.x = o->section.empty() ? "depth" : "x";
      if (cmd->count("--y") == 0) o->syn.y = o->section.empty() ? "fz" : "z";
    } else if (!o->section.empty()) {
      throw io::InputError("", "--section", o->section, "only for forming scenes (indent, indent_line, line)");
    }
    std::string card_name;
    const std::string csv = with_option_names({{"x", "--x"}, {"y", "--y"}, {"every", "--every"}, {"noise", "--noise"}}, [&] {
      if (!fe) {
        if (!o->set.empty()) throw io::InputError("", "--set", o->set.front(), "only for FE scenes (a material-point scene's inputs are its file's)");
        // With --material the scene's own card (or the default one) is not needed.
        scene::MaterialPointScene scene;
        try {
          scene = scene::read_material_point_scene(o->scene, o->material.empty() ? scene::AbsentMaterial::default_card : scene::AbsentMaterial::no_card);
        } catch (const io::InputError& e) {
          throw scene::with_kind_hint(e, o->scene, kind);  // [contact] in a file of kind tensile: is the kind right?
        }
        if (!o->material.empty()) scene.card = material::load_material_card(o->material);
        card_name = scene.card.name;
        return inverse::synthetic_measurement_csv(scene, o->syn);
      }
      auto scene = scene::read_scene(o->scene);
      if (!scene->tool_centre_path() || !scene->card())
        throw io::InputError(o->scene, "scene.kind", kind,
                             std::string("a scene of this kind has no ") + (scene->tool_centre_path() ? "material card" : "tool") +
                                 ": synth writes a material-point curve or the tool force (or a section) of an FE scene with a tool and a card");
      if (!o->material.empty()) *scene->card() = material::load_material_card(o->material);
      for (const std::string& a : o->set) set_scene_input(*scene, a);
      card_name = scene->card()->name;
      if (!o->contour_means.empty()) {
        o->syn.y = o->contour_means;
        return inverse::synthetic_contour_means_csv(*scene, o->syn);
      }
      return o->section.empty() ? inverse::synthetic_force_curve_csv(*scene, o->syn) : inverse::synthetic_section_csv(*scene, o->section, o->syn);
    });
    const std::string tmp = o->out + ".tmp";
    {
      std::ofstream f(tmp, std::ios::trunc);
      if (!f) throw io::InputError("", "--out", o->out, "cannot write");
      f << csv;
    }
    std::filesystem::rename(tmp, o->out);
    if (!g.quiet) std::cout << "wrote " << o->out << " (synthetic, card " << card_name << ", noise " << o->syn.noise << ", seed " << o->syn.seed << ")\n";
    exit_code = 0;
  });
}

}  // namespace spifit::cli

namespace spifit::cli {

}  // namespace spifit::cli
