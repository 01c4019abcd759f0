// The cone scene: a tiny one-contour cone on a 90 deg pie runs, pushes the tool up,
// and writes polar force components consistent with the Cartesian ones; the reader names file
// and key of bad inputs.
#include "forward/io/input_error.hpp"
#include "forward/scenes/cone/cone_load_map.hpp"
#include "forward/io/output_directory.hpp"
#include "forward/scenes/cone/cone_run.hpp"
#include "forward/scenes/cone/cone_scene.hpp"
#include "tests/support/csv_rows.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace spifit::scene {
namespace {

fs::path temp(const std::string& name) { return fs::temp_directory_path() / ("spifit_cone_" + std::to_string(::getpid()) + "_" + name); }

std::string material_line() { return "material = \"" + std::string(SPIFIT_SOURCE_DIR) + "/materials/aa3003o_c3c4.toml\"\n"; }

fs::path write_scene(const std::string& name, const std::string& body) {
  const fs::path f = temp(name + ".toml");
  std::ofstream(f) << "[scene]\nkind = \"cone\"\n" << material_line() << body;
  return f;
}

// One contour of a small 45 deg cone (top radius 20 mm, 0.5 mm stepdown) on a coarse 90 deg pie.
const char* kTiny =
    "[cone]\nwall_angle = 45.0\nstepdown = 0.5\ncontours = 1\ntop_radius = 20.0\npie_angle = 90.0\n"
    "[sheet]\nthickness = 1.0\nelements_per_45deg = 8\nthickness_points = 3\n"
    "[solver]\ntravel_per_increment = 0.5\n";

std::vector<std::vector<double>> read_rows(const fs::path& csv) { return test::read_csv_rows(csv); }

TEST(ConeScene, OneContourOnAPieRunsAndItsPolarForcesMatchTheCartesianOnes) {
  const fs::path file = write_scene("tiny", std::string(kTiny) + "[output]\nsteady_state = [1, 1]\n");
  const ConeScene scene = read_cone_scene(file.string());
  EXPECT_EQ(scene.stages.size(), 1u);
  EXPECT_DOUBLE_EQ(scene.clamp_radius, 21.5);  // top radius + 1.5 mm
  const fs::path dir = temp("tiny_out");
  fs::remove_all(dir);
  const auto out = io::OutputDirectory::prepare(dir.string(), true);
  const ConeResult r = run_cone_scene(scene, RunFiles(out));
  ASSERT_TRUE(r.ok()) << r.to_json().dump();
  const auto s = r.to_json();
  std::printf("tiny cone: %d elements, %d increments, %d iterations, %.2f s; peak force (%.2f, %.2f, %.2f) N, peak polar (%.2f, %.2f, %.2f) N\n",
              s["model"]["elements"].get<int>(), s["increments"].get<int>(), s["newton_iterations"].get<int>(),
              s["wall_seconds"].get<double>(), s["peak_force"][0].get<double>(), s["peak_force"][1].get<double>(),
              s["peak_force"][2].get<double>(), s["peak_polar_force"][0].get<double>(), s["peak_polar_force"][1].get<double>(),
              s["peak_polar_force"][2].get<double>());
  EXPECT_EQ(s["status"], "ok");
  EXPECT_EQ(s["contours_completed"].get<int>(), 1);
  EXPECT_EQ(s["stabilised"]["increments"].get<int>(), 0);  // none needed here
  EXPECT_EQ(s["stabilised"]["viscous_work"].get<double>(), 0.0);
  EXPECT_EQ(s["model"]["virtual_tools_deg"].size(), 2u);
  EXPECT_EQ(s["model"]["material_axes"], "fixed");  // the default (rolling direction x)
  EXPECT_GT(s["peak_force"][2].get<double>(), 0.0);  // the sheet pushes the tool up
  const auto rows = read_rows(dir / "force.csv");
  ASSERT_EQ(static_cast<int>(rows.size()), s["increments"].get<int>());
  int on_contour = 0, pushed = 0;
  double deepest_point = 0.0, deepest_surface = 0.0;
  for (const auto& row : rows) {
    ASSERT_EQ(row.size(), 16u);
    // The tool's depth in the tool-side surface includes the contact points' depth.
    EXPECT_GE(row[15], row[13]);
    deepest_point = std::max(deepest_point, row[13]);
    deepest_surface = std::max(deepest_surface, row[15]);
    const double x = row[1], y = row[2], theta = std::atan2(y, x);
    const double fx = row[5], fy = row[6], fz = row[7], fr = row[8], ft = row[9];
    const double scale = std::max(1.0, std::hypot(fx, fy));
    EXPECT_NEAR(row[4], theta * 180.0 / M_PI, 1e-9);
    EXPECT_NEAR(fr, fx * std::cos(theta) + fy * std::sin(theta), 1e-9 * scale);
    EXPECT_NEAR(ft, -fx * std::sin(theta) + fy * std::cos(theta), 1e-9 * scale);
    if (row[12] == 2.0) {  // on the contour
      ++on_contour;
      EXPECT_EQ(row[11], 1.0);
      EXPECT_GE(fz, 0.0);
      pushed += fz > 0.0 ? 1 : 0;
    }
  }
  // The last few degrees of the contour may lose contact: there the tool meets the sheet its
  // neighbour (the pie's cyclic image) formed at the start of the contour.
  EXPECT_GT(on_contour, 5);
  EXPECT_GT(pushed, 0.8 * on_contour);
  EXPECT_DOUBLE_EQ(s["max_penetration"].get<double>(), deepest_point);
  EXPECT_DOUBLE_EQ(s["max_surface_penetration"].get<double>(), deepest_surface);
  EXPECT_GT(deepest_surface, 0.0);
  const auto means = read_rows(dir / "contours.csv");
  ASSERT_EQ(means.size(), 1u);
  EXPECT_GT(means[0][5], 0.0);  // mean Fz over the central third
  // The steady state over contours [1, 1] is that contour's mean (as written to contours.csv
  // with 17 significant digits).
  ASSERT_TRUE(s.contains("steady_state"));
  EXPECT_EQ(s["steady_state"]["contours_used"].get<int>(), 1);
  EXPECT_NEAR(s["steady_state"]["polar_force"][2].get<double>(), means[0][5], 1e-12 * std::abs(means[0][5]));
  EXPECT_NEAR(s["steady_state"]["polar_force"][0].get<double>(), means[0][6], 1e-12 * std::abs(means[0][6]));
  EXPECT_NEAR(s["steady_state"]["fr_over_fz"].get<double>(), means[0][6] / means[0][5], 1e-12);
  const auto section = read_rows(dir / "sections" / "section_s1_c001.csv");
  EXPECT_GT(section.size(), 5u);
  EXPECT_EQ(section.front()[0], 0.0);  // from the axis
  EXPECT_DOUBLE_EQ(section.back()[0], 21.5);  // to the clamp
  EXPECT_TRUE(fs::exists(dir / "vtu" / "sheet.pvd"));
  fs::remove_all(dir);
  fs::remove(file);
}

TEST(ConeScene, PresetsFillTheGeometryAndTheClampRadius) {
  const fs::path f = write_scene("preset", "[cone]\npreset = \"cone70\"\ncontours = 3\n[sheet]\nelements_per_45deg = 16\nthickness_rule = \"surface\"\n");
  const ConeScene s = read_cone_scene(f.string());
  ASSERT_EQ(s.stages.size(), 1u);
  EXPECT_EQ(s.stages[0].contours, 3);
  EXPECT_DOUBLE_EQ(s.stages[0].wall_angle_deg, 70.0);
  EXPECT_DOUBLE_EQ(s.pie_angle, 45.0);
  EXPECT_DOUBLE_EQ(s.thickness, 1.2);
  EXPECT_DOUBLE_EQ(s.clamp_radius, 91.5);
  EXPECT_EQ(s.thickness_rule, element::ThicknessRuleKind::surface);
  EXPECT_EQ(s.material_axes, model::ShellModelOptions::MaterialAxes::fixed);  // rolling direction x
  EXPECT_EQ(cone_scene_mesh(s).node_sets.count("edge_theta1"), 1u);
  const fs::path polar = write_scene("polar", "[cone]\npreset = \"cone70\"\n[sheet]\nmaterial_axes = \"polar\"\n");
  EXPECT_EQ(read_cone_scene(polar.string()).material_axes, model::ShellModelOptions::MaterialAxes::polar);
  fs::remove(polar);
  const fs::path v = write_scene("vwall", "[cone]\npreset = \"vwall\"\nstages = 2\npie_angle = 90.0\n[sheet]\nelements_per_45deg = 8\n");
  const ConeScene w = read_cone_scene(v.string());
  ASSERT_EQ(w.stages.size(), 2u);
  EXPECT_DOUBLE_EQ(w.stages[1].wall_angle_deg, 60.0);
  EXPECT_DOUBLE_EQ(w.clamp_radius, 65.5);  // the vwall backing plate hole (thesis §8.1)
  EXPECT_EQ(cone_scene_path(w).segments.back().stage, 2);
  // Newton waits 3 iterations before a growing residual cuts a cone increment back (the
  // solver's default); [solver] divergence_after sets it (10 in cone70_pie45_fine.toml).
  EXPECT_EQ(s.divergence_after, 3);
  const fs::path d = write_scene("divergence", "[cone]\npreset = \"cone70\"\n[solver]\ndivergence_after = 4\n");
  EXPECT_EQ(read_cone_scene(d.string()).divergence_after, 4);
  // Stabilised increments where a run would end: off by default, [solver] stabilisation sets the factor.
  EXPECT_EQ(s.stabilisation, 0.0);
  const fs::path z = write_scene("stabilisation", "[cone]\npreset = \"cone70\"\n[solver]\nstabilisation = 1e-4\n");
  EXPECT_EQ(read_cone_scene(z.string()).stabilisation, 1e-4);
  fs::remove(f);
  fs::remove(v);
  fs::remove(d);
  fs::remove(z);
}

// The load map of a cone70 pie path: linear with slope = effective length except on the moves,
// each of which spans move_increments x travel_per_increment of load between two breakpoints.
TEST(ConeLoadMap, ShortensEveryPieMoveToItsIncrementsAndInvertsExactly) {
  const toolpath::ConePath path = toolpath::annotated_cone_path(toolpath::cone70(3, 45.0));
  const std::vector<double> d = path.path.waypoint_distances();
  const double length = d.back();
  const ConeLoadMap off = cone_load_map(path, 1.0, 0);
  EXPECT_TRUE(off.breakpoints.empty());
  EXPECT_EQ(off.map.effective_length(), length);
  for (double l : {0.0, 0.123, 0.5, 0.987, 1.0}) EXPECT_EQ(off.map.travel(l), l * length);
  const ConeLoadMap map = cone_load_map(path, 1.0, 2);
  EXPECT_EQ(map.shortened_moves, 2);  // between contours 1-2 and 2-3
  ASSERT_EQ(map.breakpoints.size(), 4u);
  double moves = 0.0;
  for (std::size_t i = 1; i < d.size(); ++i) {
    if (path.segments[i].move != toolpath::ConeMove::move) continue;
    moves += d[i] - d[i - 1];
    const double l0 = map.map.lambda(d[i - 1]), l1 = map.map.lambda(d[i]);
    EXPECT_NEAR((l1 - l0) * map.map.effective_length(), 2.0, 1e-9) << "move ending at waypoint " << i;
    EXPECT_NEAR(map.map.travel(0.5 * (l0 + l1)), 0.5 * (d[i - 1] + d[i]), 1e-9);  // linear inside the move
  }
  EXPECT_GT(moves, 80.0);  // two chords of about 2 x 90 sin(22.5 deg) = 69 mm: the saving is real
  EXPECT_NEAR(map.map.effective_length(), length - moves + 4.0, 1e-9);
  for (double s : {0.0, 10.0, 0.4 * length, 0.77 * length, length}) EXPECT_NEAR(map.map.travel(map.map.lambda(s)), s, 1e-9 * length);
  EXPECT_EQ(map.map.travel(1.0), length);
}

// [solver] estimate_next_correction (NewtonOptions): the tiny cone with and without it; the
// contour mean force stays within the tolerances' reach and the iterations do not grow.
TEST(ConeScene, EstimatedNextCorrectionKeepsTheForceWithFewerIterations) {
  double fz[2] = {0.0, 0.0};
  int iterations[2] = {0, 0};
  for (int on : {0, 1}) {
    const fs::path file = write_scene("estimate" + std::to_string(on), std::string(kTiny) + "estimate_next_correction = " + (on ? "true" : "false") + "\n");
    const fs::path dir = temp("estimate_out" + std::to_string(on));
    fs::remove_all(dir);
    const ConeResult r = run_cone_scene(read_cone_scene(file.string()), RunFiles(io::OutputDirectory::prepare(dir.string(), true)));
    ASSERT_TRUE(r.ok()) << r.to_json().dump();
    EXPECT_EQ(r.to_json()["solver"]["estimate_next_correction"].get<bool>(), on == 1);
    iterations[on] = r.to_json()["newton_iterations"].get<int>();
    const auto means = read_rows(dir / "contours.csv");
    ASSERT_EQ(means.size(), 1u);
    fz[on] = means[0][5];
    fs::remove_all(dir);
    fs::remove(file);
  }
  std::printf("tiny cone: %d / %d Newton iterations without / with the estimate, mean Fz %.6f / %.6f N\n", iterations[0], iterations[1], fz[0], fz[1]);
  EXPECT_LT(iterations[1], iterations[0]);
  EXPECT_NEAR(fz[1], fz[0], 1e-4 * std::abs(fz[0]));
}

// The move between two contours of the tiny cone in one increment (the default) instead of one
// per 0.5 mm: the second contour's mean force hardly changes (the tool is in the air on the move).
TEST(ConeScene, PieMoveInOneIncrementKeepsTheNextContoursForce) {
  std::string two(kTiny);
  two.replace(two.find("contours = 1"), 12, "contours = 2");
  double fz[2] = {0.0, 0.0};
  int move_rows[2] = {0, 0}, increments[2] = {0, 0};
  for (int n : {0, 1}) {
    const fs::path file = write_scene("move" + std::to_string(n), two + "move_increments = " + std::to_string(n) + "\n");
    const fs::path dir = temp("move_out" + std::to_string(n));
    fs::remove_all(dir);
    const ConeResult r = run_cone_scene(read_cone_scene(file.string()), RunFiles(io::OutputDirectory::prepare(dir.string(), true)));
    ASSERT_TRUE(r.ok()) << r.to_json().dump();
    EXPECT_EQ(r.to_json()["solver"]["move_increments"].get<int>(), n);
    increments[n] = r.to_json()["increments"].get<int>();
    for (const auto& row : read_rows(dir / "force.csv")) move_rows[n] += row[12] == 5.0 ? 1 : 0;
    const auto means = read_rows(dir / "contours.csv");
    ASSERT_EQ(means.size(), 2u);
    fz[n] = means[1][5];
    fs::remove_all(dir);
    fs::remove(file);
  }
  std::printf("tiny cone, 2 contours: move in %d / %d increments, %d / %d increments in all, contour 2 mean Fz %.3f / %.3f N\n",
              move_rows[0], move_rows[1], increments[0], increments[1], fz[0], fz[1]);
  EXPECT_EQ(move_rows[1], 1);
  EXPECT_GT(move_rows[0], 10);  // a chord of 2 x 20 sin(45 deg) = 28 mm at 0.5 mm per increment
  EXPECT_NEAR(fz[1], fz[0], 0.02 * std::abs(fz[0]));
}

// Energy account of two contours of the tiny cone: the tool's work equals the
// layers' elastic and plastic energy, the shear energy, the penalty energy, the frictional
// dissipation and the energy released by the contact offset at the thickness updates
// (model::ModelEnergies). Measured: -0.74 % of the work without friction at 0.5 mm per
// increment; with mu = 0.1 at 0.125 mm per increment 2.5e-5 (at 0.5 mm 3.5 %: the points
// entering and leaving contact within an increment).
TEST(ConeScene, EnergyAccountBalancesTheToolsWork) {
  std::string two(kTiny);
  two.replace(two.find("contours = 1"), 12, "contours = 2");
  struct Case {
    double mu, travel, tolerance;
  };
  for (const Case c : {Case{0.0, 0.5, 0.015}, Case{0.1, 0.125, 5e-4}}) {
    std::string body = two;
    body.replace(body.find("travel_per_increment = 0.5"), 26, "travel_per_increment = " + std::to_string(c.travel));
    body += "[contact]\nfriction = " + std::to_string(c.mu) + "\n";
    const fs::path file = write_scene("energy", body);
    const fs::path dir = temp("energy_out");
    fs::remove_all(dir);
    const ConeResult r = run_cone_scene(read_cone_scene(file.string()), RunFiles(io::OutputDirectory::prepare(dir.string(), true)));
    ASSERT_TRUE(r.ok()) << r.to_json().dump();
    const auto e = r.to_json()["energies"];
    const double work = e["external_work"].get<double>(), error = e["balance_error"].get<double>();
    std::printf("tiny cone, mu %.2f, %.3f mm per increment: work %.2f N mm, plastic %.2f, elastic %.2f, friction %.2f, offset release %.2f, error %.3f (%.2e)\n",
                c.mu, c.travel, work, e["plastic"].get<double>(), e["elastic"].get<double>(), e["friction_dissipation"].get<double>(),
                e["contact_offset_release"].get<double>(), error, error / work);
    EXPECT_GT(work, 1000.0);
    EXPECT_LT(std::abs(error), c.tolerance * work);
    EXPECT_GT(e["contact_offset_release"].get<double>(), 0.01 * work);  // the sheet thins under the tool
    if (c.mu > 0.0) EXPECT_GT(e["friction_dissipation"].get<double>(), 0.2 * work);
    else EXPECT_EQ(e["friction_dissipation"].get<double>(), 0.0);
    // energies.csv: one row per increment, the last equal to the summary's account.
    const auto rows = read_rows(dir / "energies.csv");
    ASSERT_EQ(static_cast<int>(rows.size()), r.to_json()["increments"].get<int>());
    ASSERT_EQ(rows.back().size(), 9u);
    EXPECT_NEAR(rows.back()[1], work, 1e-9 * work);
    EXPECT_NEAR(rows.back()[8], error, 1e-9 * work);
    fs::remove_all(dir);
    fs::remove(file);
  }
}

TEST(ConeScene, ReaderErrorsNameFileKeyAndValue) {
  struct Case {
    std::string body, key, value, fragment;
  };
  const std::vector<Case> cases = {
      {"[cone]\npreset = \"cone60\"\n", "cone.preset", "\"cone60\"", "unknown preset"},
      {"[cone]\npreset = \"cone70\"\npie_angle = 0.0\n", "cone.pie_angle", "0", "(0, 360]"},
      {"[cone]\npreset = \"cone70\"\npie_angle = 50.0\n", "cone.pie_angle", "50", "integer"},
      {"[cone]\npreset = \"cone70\"\n[sheet]\nclamp_radius = 85.0\n", "sheet.clamp_radius", "85", "top radius 90"},
      {"[cone]\npreset = \"cone70\"\ncontours = 0\n", "cone.contours", "0", ">= 1"},
      {"[cone]\npreset = \"vwall\"\nwall_angle = 60.0\n", "cone.wall_angle", "60", "per stage"},
      {"[cone]\nwall_angle = 45.0\nstepdown = 0.5\ncontours = 2\ntop_radius = 20.0\n", "sheet.thickness", "0", "thickness"},
      {"[cone]\npreset = \"cone70\"\n[sheet]\nelements_per_45deg = 1\n", "sheet.elements_per_45deg", "1", "[2, 2000]"},
      {"[cone]\npreset = \"cone70\"\n[contact]\nvirtual_tool = false\n", "contact.virtual_tool", "", "unknown key"},
      {"[cone]\npreset = \"cone70\"\n[output]\nsteady_state = [60, 80]\n", "output.steady_state", "", "<= 60"},
      {"[cone]\npreset = \"cone70\"\n[output]\nsteady_state = [5]\n", "output.steady_state", "", "[from, to]"},
      {"[cone]\npreset = \"cone70\"\n[solver]\nmove_increments = -1\n", "solver.move_increments", "-1", "[0, 1000]"},
      {"[cone]\npreset = \"cone70\"\n[solver]\nestimate_next_correction = 1\n", "solver.estimate_next_correction", "1", "true or false"},
      {"[cone]\npreset = \"cone70\"\n[solver]\ndivergence_after = -1\n", "solver.divergence_after", "-1", "[0, 1000]"},
      {"[cone]\npreset = \"cone70\"\n[solver]\nstabilisation = 2.0\n", "solver.stabilisation", "2", "[0, 1]"},
      {"[cone]\npreset = \"cone70\"\n[sheet]\nthickness_rule = \"lobatto\"\n", "sheet.thickness_rule", "\"lobatto\"", "\"surface\""},
      {"[cone]\npreset = \"cone70\"\n[sheet]\nthickness_rule = \"surface\"\nthickness_points = 4\n", "sheet.thickness_rule", "", "odd number"},
      {"[cone]\npreset = \"cone70\"\n[sheet]\nmax_sector_deg = 60.0\n", "sheet.max_sector_deg", "60", "45 or 90"},
      {"[cone]\npreset = \"cone70\"\n[sheet]\nmaterial_axes = \"radial\"\n", "sheet.material_axes", "\"radial\"", "\"polar\""},
      {"[cone]\npreset = \"vwall\"\n[sheet]\nring_start = 10.0\ncore_radius = 26.0\n", "sheet", "", "ring_start must lie beyond the core"},
  };
  for (const auto& c : cases) {
    const fs::path f = write_scene("bad", c.body);
    try {
      read_cone_scene(f.string());
      ADD_FAILURE() << "no error for " << c.body;
    } catch (const io::InputError& e) {
      std::printf("%s\n", e.what());
      EXPECT_EQ(e.file(), f.string());
      EXPECT_EQ(e.key(), c.key) << e.what();
      if (!c.value.empty()) {
        EXPECT_EQ(e.value(), c.value) << e.what();
      }
      EXPECT_NE(std::string(e.what()).find(c.fragment), std::string::npos) << e.what();
    }
    fs::remove(f);
  }
}

// Every bundled cone scene reads, meshes and passes the mesh checks (the long ones are run on
// demand only, so nothing else would notice a scene file that cannot start).
TEST(ConeScene, EveryBundledConeSceneReads) {
  int n = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(SPIFIT_SOURCE_DIR) / "experiments/aa3003o/scenes")) {
    const std::string name = entry.path().filename().string();
    if (entry.path().extension() != ".toml" || !(name.rfind("cone", 0) == 0 || name.rfind("vwall", 0) == 0)) continue;
    EXPECT_NO_THROW({
      const ConeScene s = read_cone_scene(entry.path().string());
      EXPECT_GT(cone_scene_mesh(s).num_elements(), 0);
    }) << name;
    ++n;
  }
  EXPECT_GE(n, 13);  // cone50 x 3, cone70 x 6 (short, coarse 60/100, fine 60/60 loose/100), vwall x 4
}

// Steady state = mean of the contour means in the range; contours without samples (or not
// completed) do not count.
TEST(ConeScene, SteadyStateAveragesTheContourMeansInItsRange) {
  std::vector<ContourMean> m(4);
  for (int k = 0; k < 4; ++k) {
    m[static_cast<std::size_t>(k)].samples = 10;
    m[static_cast<std::size_t>(k)].polar = Eigen::Vector3d(-(k + 1.0), 0.5 * k, 100.0 * (k + 1));
    m[static_cast<std::size_t>(k)].force = m[static_cast<std::size_t>(k)].polar;
  }
  m[2].samples = 0;  // no sample in its central third
  const SteadyState s = steady_state(m, 2, 6);
  EXPECT_EQ(s.contours, 2);  // contours 2 and 4
  EXPECT_DOUBLE_EQ(s.polar.z(), 300.0);
  EXPECT_DOUBLE_EQ(s.polar.x(), -3.0);
  EXPECT_EQ(steady_state(m, 5, 6).contours, 0);
  EXPECT_TRUE(std::isnan(steady_state(m, 5, 6).polar.z()));
}

}  // namespace
}  // namespace spifit::scene
