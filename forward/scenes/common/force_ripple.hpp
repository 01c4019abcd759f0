#pragma once
// The ripple of the tool force: how far a force component departs from its running mean over
// one element length of travel. A sheet of bilinear shells cannot follow a sphere smoothly, so
// the force oscillates with the period of the element size as the tool crosses elements; the
// thesis saw "large oscillations ... if the mesh is not fine enough" (§3.3, its GUI's smoothing)
// and "small parasitic oscillations due to the FE mesh and ... the discrete location of the
// integration points of the contact elements" (§9.1). A centred mean over one period removes
// the oscillation and passes a linear trend unchanged, so what is left is the ripple.
//
// Only steady travel is looked at: windows in which the tool stays at one height and turns by at
// most 45 degrees in plane (no plunge, no ramp, no corner), with at least 7 force samples
// (increments of at most about a sixth of an element: coarser ones do not resolve the ripple, and
// none is given).
#include "forward/scenes/common/tool_force_history.hpp"

#include <string>
#include <vector>

namespace spifit::scene {

struct ForceRipple {
  int windows = 0;          // steady windows looked at (0: no steady travel resolved)
  double amplitude = 0.0;   // largest |F_k - running mean of F_k| over the peak |F| of the run
  double travel = 0.0;      // mm of tool travel where it is largest
  int component = 0;        // k: 0 x, 1 y, 2 z
  double window = 0.0;      // mm of travel the mean is taken over
};

// samples in the order run; window > 0 (the element size).
ForceRipple force_ripple(const std::vector<ToolForceSample>& samples, double window);

// The warning when amplitude > kRippleWarningFraction, else "". The threshold and the
// measurements behind it: docs/design/decisions.md, "Force-ripple warning".
constexpr double kRippleWarningFraction = 0.10;
std::string ripple_warning(const ForceRipple& r);

}  // namespace spifit::scene
