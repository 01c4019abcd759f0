#pragma once
// The named inputs the tool scenes share (io/named_inputs.hpp): [contact] and [solver], the
// [tool] radius, feed and spin, and the [output] steps of VTU files and checkpoints. Declared on any scene struct with the members they name
// (forming_scene.hpp, cone_scene.hpp); the defaults are the struct's.
#include "forward/io/named_inputs.hpp"
#include "forward/scenes/common/scene_tables.hpp"
#include "forward/solver/linear_solver.hpp"

#include <optional>
#include <string>

namespace spifit::scene {

template <typename Scene>
void add_contact_inputs(io::InputTable<Scene>& t) {
  using io::Range;
  t.real({"contact.penalty", {}, "N/mm^3", Range::positive(), {},
          "penalty coefficient K_p: contact pressure per mm of penetration (thesis §7.1 used 1e2..1e5)", true},
         [](Scene& s) -> double& { return s.contact.penalty; });
  t.real({"contact.friction", {}, "", Range::closed(0.0, 2.0), {}, "Coulomb friction coefficient mu between tool and sheet", true},
         [](Scene& s) -> double& { return s.contact.friction; });
  t.real({"contact.tangential_penalty", {}, "N/mm^3", Range::non_negative(), {},
          "tangential (stick) penalty K_t of the regularised friction; 0: equal to the penalty", true},
         [](Scene& s) -> double& { return s.contact.tangential_penalty; });
  t.integer({"contact.points", {}, "", Range::closed(1, 6), {}, "contact points per direction and element (n x n)", true},
            [](Scene& s) -> int& { return s.contact.points; });
  t.text({"contact.surface", {}, "", {}, {"flat", "phong"},
          "tool-side surface the tool sees: bilinear facets, or facets curved with the nodal directors", false},
         {[](const Scene& s) -> std::string { return s.contact.surface == contact::ContactOptions::Surface::phong ? "phong" : "flat"; },
          [](Scene& s, const std::string& v) {
            s.contact.surface = v == "phong" ? contact::ContactOptions::Surface::phong : contact::ContactOptions::Surface::flat;
            return true;
          }});
  t.text({"contact.method", {}, "", {}, {"penalty", "mst"},
          "explicit scheme: penalty contact, or the Moving Spherical Tool (forces for zero penetration and exact Coulomb friction)", false},
         {[](const Scene& s) -> std::string { return s.contact.method == contact::ContactOptions::Method::mst ? "mst" : "penalty"; },
          [](Scene& s, const std::string& v) {
            s.contact.method = v == "mst" ? contact::ContactOptions::Method::mst : contact::ContactOptions::Method::penalty;
            return true;
          }});
}

// The explicit scheme's keys of [solver] (solver::ExplicitOptions) on the fields explicit_scheme
// and explicit_options.
template <typename Scene>
void add_explicit_inputs(io::InputTable<Scene>& t) {
  using io::Range;
  t.text({"solver.scheme", {}, "", {}, {"implicit", "explicit"},
          "time integration: static Newton increments (implicit) or central differences with a lumped mass (explicit)", false},
         {[](const Scene& s) -> std::string { return s.explicit_scheme ? "explicit" : "implicit"; },
          [](Scene& s, const std::string& v) {
            s.explicit_scheme = v == "explicit";
            return true;
          }});
  t.real({"solver.mass_scaling", {}, "", Range::positive(), {}, "explicit: density factor of every element (the stable step grows with its square root)", true},
         [](Scene& s) -> double& { return s.explicit_options.mass_scaling; });
  t.real({"solver.rotational_mass_scaling", {}, "", Range::positive(), {}, "explicit: extra factor on the rotational inertia", true},
         [](Scene& s) -> double& { return s.explicit_options.rotational_scaling; });
  t.real({"solver.target_time_step", {}, "s", Range::non_negative(), {},
          "explicit: selective mass scaling of the elements whose stable step is below this (0: off)", true},
         [](Scene& s) -> double& { return s.explicit_options.target_time_step; });
  t.real({"solver.time_scaling", {}, "", Range::positive(), {}, "explicit: the tool runs this many times faster than its feed", true},
         [](Scene& s) -> double& { return s.explicit_options.time_scaling; });
  t.real({"solver.damping", {}, "1/s", Range::non_negative(), {}, "explicit: mass-proportional damping coefficient", true},
         [](Scene& s) -> double& { return s.explicit_options.damping; });
  t.real({"solver.bulk_viscosity_linear", {}, "", Range{0.0, 1.0, false, true}, {},
          "explicit: bulk viscosity against the elements' area rate, linear term b1 (about the fraction of critical damping of the highest mode)", true},
         [](Scene& s) -> double& { return s.explicit_options.bulk_viscosity_linear; });
  t.real({"solver.bulk_viscosity_quadratic", {}, "", Range::non_negative(), {}, "explicit: bulk viscosity, quadratic term b2 (in compression only)", true},
         [](Scene& s) -> double& { return s.explicit_options.bulk_viscosity_quadratic; });
  t.real({"solver.time_step_safety", {}, "", Range{0.0, 1.0, true, false}, {}, "explicit: time step over the smallest element bound", false},
         [](Scene& s) -> double& { return s.explicit_options.safety; });
  t.real({"solver.max_steps", {}, "", Range::at_least(1.0), {}, "explicit: a run needing more steps stops at start-up", false},
         [](Scene& s) -> double& { return s.explicit_options.max_steps; });
}

template <typename Scene>
void add_solver_inputs(io::InputTable<Scene>& t) {
  using io::Range;
  t.real({"solver.travel_per_increment", {}, "mm", Range::positive(), {}, "tool travel per increment (the largest; cut back on failure)", true},
         [](Scene& s) -> double& { return s.travel_per_increment; });
  t.integer({"solver.max_iterations", {}, "", Range::closed(1, 1000), {}, "Newton iterations before an increment is cut back", false},
            [](Scene& s) -> int& { return s.max_iterations; });
  t.text({"solver.linear_solver", {}, "", {}, {"auto", "umfpack", "cholmod"},
          "sparse solver: by the tangent's symmetry (auto), UMFPACK (general) or CHOLMOD (symmetric positive definite)", false},
         {[](const Scene& s) -> std::string { return s.linear_solver ? solver::to_string(*s.linear_solver) : "auto"; },
          [](Scene& s, const std::string& v) {
            solver::LinearSolverKind k{};
            if (!solver::linear_solver_from_string(v, &k)) return false;
            s.linear_solver = k;
            return true;
          }});
  t.text({"solver.tangent", {}, "", {}, {"auto", "exact", "symmetrised"},
          "a non-symmetric tangent (friction, kinematic hardening): its symmetric part with CHOLMOD (auto: while friction <= 0.2) or exact with UMFPACK", false},
         {[](const Scene& s) -> std::string { return to_string(s.tangent); },
          [](Scene& s, const std::string& v) { return friction_tangent_from_string(v, &s.tangent); }});
  t.boolean({"solver.extrapolate", {}, "", {}, {}, "start each increment from the previous increment's displacement, scaled", false},
            [](Scene& s) -> bool& { return s.extrapolate; });
  t.boolean({"solver.line_search", {}, "", {}, {}, "energy line search on every Newton correction", false},
            [](Scene& s) -> bool& { return s.line_search; });
  t.real({"solver.force_tolerance", {}, "", Range::closed(1e-12, 1e-2), {}, "relative residual force of a converged increment", true},
         [](Scene& s) -> double& { return s.force_tolerance; });
  t.real({"solver.displacement_tolerance", {}, "", Range::closed(1e-12, 1e-2), {},
          "last correction over the increment's displacement of a converged increment", true},
         [](Scene& s) -> double& { return s.displacement_tolerance; });
  t.integer({"solver.divergence_after", {}, "", Range::closed(0, 1000), {},
             "iterations before a growing residual cuts the increment back (0: never)", false},
            [](Scene& s) -> int& { return s.divergence_after; });
  t.boolean({"solver.estimate_next_correction", {}, "", {}, {}, "accept an increment on the estimated next correction", false},
            [](Scene& s) -> bool& { return s.estimate_next_correction; });
  t.real({"solver.stabilisation", {}, "", Range::closed(0.0, 1.0), {}, "damping of an increment failing at the minimum increment (0: off)", false},
         [](Scene& s) -> double& { return s.stabilisation; });
  add_explicit_inputs(t);
}

// [tool] radius, feed, spin on the fields `radius`, feed and spin.
template <typename Scene>
void add_tool_inputs(io::InputTable<Scene>& t, double Scene::*radius) {
  using io::Range;
  t.real({"tool.radius", {}, "mm", Range::positive(), {}, "radius of the spherical tool", true}, [radius](Scene& s) -> double& { return s.*radius; });
  t.real({"tool.feed", {}, "mm/s", Range::positive(), {}, "tool feed rate along its path (times in force.csv)", false},
         [](Scene& s) -> double& { return s.feed; });
  t.real({"tool.spin", {}, "rev/min", Range::closed(-1e5, 1e5), {}, "tool rotation about +z, counter-clockwise seen from above; acts through friction", true},
         [](Scene& s) -> double& { return s.spin; });
}

// [output] vtu_every, checkpoint_every and checkpoint_increments on the fields of those names
// (scene_tables.hpp: tool_output_options); `marks` says what checkpoint_every counts.
template <typename Scene>
void add_output_inputs(io::InputTable<Scene>& t, const std::string& marks) {
  using io::Range;
  t.integer({"output.vtu_every", {}, "", Range::non_negative(), {}, "increments between VTU steps (0: initial and final state only)", false},
            [](Scene& s) -> int& { return s.vtu_every; });
  t.integer({"output.checkpoint_every", {}, "", Range::non_negative(), {}, marks + " between checkpoints (0: none)", false},
            [](Scene& s) -> int& { return s.checkpoint_every; });
  t.integer({"output.checkpoint_increments", {}, "", Range::non_negative(), {}, "increments between checkpoints (0: none)", false},
            [](Scene& s) -> int& { return s.checkpoint_increments; });
}

}  // namespace spifit::scene
