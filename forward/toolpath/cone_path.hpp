#pragma once
// Contour tool paths of SPIF cones (thesis §4.1.2, §8.1, Figs. 8.2 and 8.5, §9.1). The
// waypoints are positions of the tool CENTRE in the global frame of the project: the
// sheet's mid-surface is z = 0, its initial top (tool-side) surface z = t/2, the tool comes
// from +z, the cone axis is the z axis, polar angle theta measured from +x towards +y.
// docs/design/cone.md describes the same with the numbers of the presets.
//
// Geometry, in the (r, z) half-plane of any polar angle:
// - CAD surface = the part's inner, tool-side surface, the cone
//     r_cad(z) = r_top + (z - t/2) / tan(alpha),   z <= t/2,
//   i.e. the line through (r_top, t/2) with downward direction d = (-cos alpha, -sin alpha).
//   alpha = 90 deg is a cylinder (1/tan alpha = 0 exactly, r_cad = r_top).
// - Its unit normal towards the tool (into the part's cavity: towards the axis and up) is
//     n = (-sin alpha, +cos alpha).
// - Contour k = 1..N touches the CAD surface at depth k dz below the top surface:
//     z_k = t/2 - k dz,   r_k = r_top - k dz / tan(alpha).
// - The tool centre is the touching point moved by R along n:
//     r_c(k) = r_k - R sin(alpha),   z_c(k) = z_k + R cos(alpha),
//   so the tool tip (z_c - R) lies R (1 - cos alpha) below the touching point. The
//   centres of all contours lie on a cone parallel to the CAD surface (offset by R).
//
// Path of one cone (every segment at `feed`, no rapids; see docs/design/cone.md for numbers):
// - Start: tool centre above the start of contour 1 with its tip at t/2 + approach_clearance;
//   a vertical approach down to contour 1. The end of the path is a vertical retract from the
//   end of contour N back to the same height.
// - Full disc (pie_angle_deg = 360): contours start at theta_s = stepdown_angle_deg. Contour 1
//   is a full turn from theta_s. The stepdown k -> k+1 is a ramp from theta_s that descends
//   at ramp_angle_deg from the horizontal while advancing in the direction of travel: it lies on
//   the tool-centre cone (the tool stays on the CAD surface), its heading is constant (r and z
//   linear in the horizontal arc length s: dz/ds = -tan(ramp), dr/ds = -tan(ramp)/tan(alpha)),
//   so it ends after a horizontal length dz / tan(ramp) at theta_s + dtheta_k. Contour k+1
//   starts where the ramp ends and runs back to theta_s (a turn minus dtheta_k), so that every
//   stepdown of the stage is at the same place, as in the thesis (§8.1.1: one stepdown location
//   per stage). The last contour is a full turn, so that the final depth is formed all round.
//   ramp_angle_deg (default 10) is an assumption: the thesis only shows the ramps (Fig. 8.2f).
// - Pie (pie_angle_deg = gamma < 360; thesis Fig. 8.5, §9.1.2): each contour is the arc from
//   one pie edge to the other, theta = 0 -> gamma counter-clockwise (gamma -> 0 clockwise);
//   stepdown_angle_deg and ramp_angle_deg are not used. After contour k < N the tool lifts
//   vertically by `lift` above that contour, moves in a straight horizontal line to above the
//   start of contour k+1 and plunges vertically (lift + dz) onto it.
// - Contours always turn in the same direction (counter_clockwise seen from +z or not).
// - Arcs (and ramps) are cut into chords whose sagitta is <= chord_tolerance (angle
//   4 asin(sqrt(tol / 2r)), at most a quarter turn, as the G-code reader does for G02/G03).
// - The vertical lift/retract departs from a wall of angle alpha at cos(alpha) mm per mm of
//   lift: at 90 deg it slides along the wall (tangent, no penetration).
#include "forward/toolpath/tool_path.hpp"

#include <vector>

namespace spifit::toolpath {

// The first six fields are required: their default 0 is rejected by check_cone_path_options.
struct ConePathOptions {
  double wall_angle_deg = 0.0;     // alpha, angle of the wall from the horizontal, in (0, 90]
  double stepdown = 0.0;           // dz between contours, mm, > 0
  int contours = 0;                // N >= 1
  double top_radius = 0.0;         // r_top of the CAD surface at z = t/2, mm, > 0
  double thickness = 0.0;          // t, mm, > 0; mid-surface z = 0, top surface z = t/2
  double tool_radius = 0.0;        // R, mm, > 0
  double pie_angle_deg = 360.0;    // gamma in (0, 360]: 360 = full disc, else pie 0..gamma
  bool counter_clockwise = true;   // direction of travel seen from +z, the same for all contours
  double stepdown_angle_deg = 0.0; // full disc: polar angle of the contour starts and ramps
  double ramp_angle_deg = 10.0;    // full disc: ramp descent angle in (0, alpha) (assumption)
  double feed = 2000.0 / 60.0;     // mm/s on every segment (thesis §3.2.1: 2000 mm/min)
  double lift = 2.0;               // pie: lift above the contour just finished, mm, > 0
  double chord_tolerance = 0.005;  // max distance between an arc and its chords, mm
  double approach_clearance = 1.0; // tip height above z = t/2 at the start and end, mm, >= 0
};

// Throws std::invalid_argument naming the first offending option (e.g. "cone path:
// wall_angle_deg = 95 must lie in (0, 90]"); also when the last contour's tool centre would
// reach the axis (r_c(N) <= 0), a ramp longer than half a turn, or more than 10^7 waypoints.
void check_cone_path_options(const ConePathOptions& o);

// Waypoints of the tool centre, every segment at o.feed (see the header comment).
ToolPath cone_path(const ConePathOptions& o);

// Geometry of contour k in [0, N] (k = 0: the initial top surface): the tool centre's
// horizontal radius r_c(k) and height z_c(k), and the touching point on the CAD surface.
double cone_contour_centre_radius(const ConePathOptions& o, int k);
double cone_contour_centre_z(const ConePathOptions& o, int k);
double cone_contour_touch_radius(const ConePathOptions& o, int k);
double cone_contour_touch_z(const ConePathOptions& o, int k);
// Height of the tool centre at the start and end of the path: t/2 + approach_clearance + R.
double cone_approach_centre_z(const ConePathOptions& o);
// Full disc: polar angle (rad, > 0) swept by the ramp from contour k to k+1, k in [1, N-1].
double cone_ramp_sweep(const ConePathOptions& o, int k);

// What each segment of a cone path does, for scenes and observables (e.g. averaging the force
// over the central third of each contour, thesis §8.3 footnote 8).
enum class ConeMove { start, approach, contour, ramp, lift, move, plunge, retract, stage_change };
struct ConeSegment {
  ConeMove move = ConeMove::start;
  int stage = 1;    // 1-based stage (multistage paths), 1 for a single cone
  int contour = 0;  // contour: its number; approach/ramp/lift/move/plunge: the contour it leads
                    // to; retract: N; start and stage_change: 0
};
struct ConePath {
  ToolPath path;
  std::vector<ConeSegment> segments;  // segments[i]: the segment ending at waypoint i;
                                      // segments[0] = {start, 1, 0}
};
ConePath annotated_cone_path(const ConePathOptions& o);

// Multistage forming (vwall, thesis §8.1.1): the stages one after another, each with its own
// options. Between stages the tool (after the stage's retract) rises vertically to the centre
// height safe_z, moves horizontally to above the next stage's start and descends to the
// next stage's approach height. safe_z must be >= every stage's cone_approach_centre_z.
ToolPath multistage_cone_path(const std::vector<ConePathOptions>& stages, double safe_z);
ConePath annotated_multistage_cone_path(const std::vector<ConePathOptions>& stages,
                                        double safe_z);

// Presets (docs/design/cone.md, "Presets"). Tool radius 5 mm (10 mm sphere, thesis §8.1.1,
// §9.1.1); feed 2000 mm/min.
// cone50 (§4.1.2 = stage 1 of §8.1): alpha 50, dz 1 mm, 30 contours, t 1.5 mm, r_top 64 mm,
// stepdown at 6 deg (stage 1's); the thesis simulated a quarter (pie 90).
ConePathOptions cone50(double pie_deg = 90.0);
// cone70 (§9.1): alpha 70, dz 0.5 mm, 60 (30 mm deep) or 100 (50 mm) contours, t 1.2 mm,
// r_top 90 mm, 45 deg pie in the thesis; stepdown angle 0 (not given in the thesis).
ConePathOptions cone70(int contours = 60, double pie_deg = 45.0);
// vwall (§8.1): 5 stages at 50, 60, 70, 80, 90 deg, 30 contours of dz 1 mm each (30 mm deep),
// t 1.5 mm, r_top 64 mm (top diameter 128 mm), stepdowns at 6, -177, -118, 43, -45 deg.
std::vector<ConePathOptions> vwall_stages(double pie_deg = 360.0);

}  // namespace spifit::toolpath
