// Saving and restoring the state of a shell model with a tool (model::save_model_state /
// load_model_state) and of the Newton solver (NewtonSolver::state / set_state / resume): a plastic
// sheet ploughed by a spinning tool with friction and two rotated tool copies, stopped after a
// few increments, saved, restored into freshly built objects and continued, follows the
// uninterrupted run bit for bit (forces, displacements, iterations, cut-backs).
#include "forward/io/binary_archive.hpp"
#include "forward/material/material_card.hpp"
#include "forward/mesh/square_sheet.hpp"
#include "forward/model/model_archive.hpp"
#include "forward/model/tool_contact.hpp"
#include "forward/model/shell_model.hpp"
#include "forward/solver/newton_solver.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <memory>
#include <vector>

namespace spifit::model {
namespace {

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

// The sheet, its tool and the solver, built the same way every time.
struct Rig {
  mesh::Mesh mesh;
  std::unique_ptr<ShellModel> model;
  model::ToolContact* tool = nullptr;
  std::unique_ptr<solver::DofConstraints> constraints;
  std::unique_ptr<solver::NewtonSolver> solver;

  Rig() {
    mesh::SquareSheetOptions so;
    so.length_x = so.length_y = 12.0;
    so.nx = so.ny = 12;
    mesh = mesh::square_sheet(so);
    const auto card = material::load_material_card(std::string(SPIFIT_SOURCE_DIR) + "/materials/aa3003o_c3c4.toml");
    ShellModelOptions mo;
    mo.shell.thickness_points = 3;
    model = std::make_unique<ShellModel>(mesh, 1.0, card.params, mo);
    contact::ContactOptions co;
    co.penalty = 1000.0;
    co.friction = 0.1;
    co.points = 2;
    const double R = 3.0, top = 0.5;
    // Plunge 0.4 mm at x = 2, then drag along y; the copies at +-90 deg touch the sheet too.
    tool = &model::attach_tool(*model, R, [=](double lambda) {
      const double press = std::min(lambda / 0.3, 1.0), travel = std::max(lambda - 0.3, 0.0) / 0.7;
      return Eigen::Vector3d(2.0, -1.0 + 2.0 * travel, top + R - 0.4 * press);
    }, co, 3.0);
    tool->set_copies({90.0, -90.0});
    constraints = std::make_unique<solver::DofConstraints>(model->num_dofs());
    for (int n : mesh.node_sets.at("boundary"))
      for (int k = 0; k < 6; ++k) constraints->prescribe(ShellModel::dof(n, k));
    constraints->finalize();
    solver::NewtonOptions o;
    o.initial_increment = o.max_increment = 0.05;
    o.min_increment = 1e-4;
    o.extrapolate = true;
    o.force_tolerance = o.displacement_tolerance = 1e-6;
    solver = std::make_unique<solver::NewtonSolver>(*model, *constraints, o);
  }

  std::vector<std::uint64_t> fingerprint() const {
    std::vector<std::uint64_t> f;
    for (int n = 0; n < model->num_nodes(); ++n)
      for (int i = 0; i < 3; ++i) {
        f.push_back(bits(model->position(n)(i)));
        f.push_back(bits(model->director(n)(i)));
      }
    for (double h : model->nodal_thickness()) f.push_back(bits(h));
    return f;
  }
};

struct Trace {
  std::vector<std::uint64_t> force_bits;  // tool force after each increment
  std::vector<int> iterations;
  void add(const model::ToolContact& t, const solver::IncrementReport& r) {
    const Eigen::Vector3d f = t.force();
    for (int i = 0; i < 3; ++i) force_bits.push_back(bits(f(i)));
    iterations.push_back(r.iterations);
  }
};

std::string save(const Rig& rig) {
  io::BinaryWriter w("model-state-test", 1);
  model::save_model_state(w, *rig.model);
  solver::save_newton_state(w, rig.solver->state());
  return w.finish();
}

void load(Rig& rig, const std::string& bytes) {
  io::BinaryReader r(bytes, "model-state-test", 1);
  model::load_model_state(r, rig.model.get());
  rig.solver->set_state(solver::load_newton_state(r));
  r.finish();
}

TEST(ShellModelState, ResumedRunFollowsTheUninterruptedOneBitForBit) {
  Rig whole;
  Trace a;
  const auto ra = whole.solver->solve(0.0, 1.0, [&](const solver::IncrementReport& r) {
    a.add(*whole.tool, r);
    return true;
  });
  ASSERT_TRUE(ra.converged) << ra.message;
  ASSERT_GT(ra.counters.increments, 12);
  std::printf("uninterrupted: %d increments, %d iterations, %d cut-backs, factorisations %d CHOLMOD + %d UMFPACK\n",
              ra.counters.increments, ra.counters.iterations, ra.counters.cutbacks, ra.counters.cholmod_factorisations,
              ra.counters.umfpack_factorisations);
  EXPECT_GT(whole.tool->summary_of_tool(1).active_points + whole.tool->summary_of_tool(2).active_points, 0)
      << "the copies should touch the sheet";

  const int stop = 9;
  Rig first;
  Trace b;
  const auto rb = first.solver->solve(0.0, 1.0, [&](const solver::IncrementReport& r) {
    b.add(*first.tool, r);
    return r.index < stop;
  });
  ASSERT_FALSE(rb.converged);
  ASSERT_EQ(rb.counters.increments, stop);
  const std::string bytes = save(first);
  std::printf("model + Newton state of %d elements (3 layers, 3 tools): %zu bytes\n", first.model->num_elements(), bytes.size());

  Rig second;  // built afresh, as a resumed process would
  load(second, bytes);
  EXPECT_EQ(save(second), bytes) << "save(load(x)) must be x";
  EXPECT_EQ(second.fingerprint(), first.fingerprint());
  const auto rc = second.solver->resume(1.0, [&](const solver::IncrementReport& r) {
    b.add(*second.tool, r);
    return true;
  });
  ASSERT_TRUE(rc.converged) << rc.message;
  EXPECT_EQ(rc.counters.increments, ra.counters.increments);
  EXPECT_EQ(rc.counters.iterations, ra.counters.iterations);
  EXPECT_EQ(rc.counters.cutbacks, ra.counters.cutbacks);
  EXPECT_EQ(rc.counters.factorisations(), ra.counters.factorisations());
  EXPECT_EQ(b.iterations, a.iterations);
  EXPECT_EQ(b.force_bits, a.force_bits);
  EXPECT_EQ(second.fingerprint(), whole.fingerprint());
}

TEST(ShellModelState, AStateOfAnotherModelIsRefused) {
  Rig rig;
  const std::string bytes = save(rig);
  mesh::SquareSheetOptions so;
  so.length_x = so.length_y = 12.0;
  so.nx = so.ny = 10;
  const mesh::Mesh other_mesh = mesh::square_sheet(so);
  material::MaterialParams<double> elastic;
  elastic.plastic = false;
  ShellModel other(other_mesh, 1.0, elastic, {});
  io::BinaryReader r(bytes, "model-state-test", 1);
  try {
    model::load_model_state(r, &other);
    ADD_FAILURE() << "a state of 169 nodes loaded into a model of 121";
  } catch (const io::ArchiveError& e) {
    EXPECT_NE(std::string(e.what()).find("169 nodes, the model has 121"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace spifit::model
