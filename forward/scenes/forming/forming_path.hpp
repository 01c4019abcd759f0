#pragma once
// The tool path of a forming scene: its named points or a G-code program for the tool tip, the
// tool centre's path (the tip lifted by the sheet's half thickness and the tool radius), and
// the marks where the run stops to take sections (the named points; for G-code the corners).
#include "forward/scenes/common/run_observer.hpp"
#include "forward/scenes/forming/forming_scene.hpp"
#include "forward/toolpath/tool_path.hpp"

#include <vector>

namespace spifit::scene {

// The tool-tip path of a G-code program. The position before the first move is unknown to the
// program, so an opening rapid (G00) only places the tool: the path starts at its end point
// instead of at the reader's default start (the origin).
toolpath::ToolPath gcode_tip_path(const std::string& file);

// The path of the tool centre: the tip path lifted by t/2 + R.
toolpath::ToolPath forming_centre_path(const FormingScene& scene);

// Marks of the run: each named point after the first, at its travel; for a G-code path the
// points where it turns by more than 15 degrees (named "line N", the program line) and its end
// ("end"). The run does not step over them, and its increment size starts afresh at each, as
// after a change of direction (arc chords turn by far less and are not marks).
std::vector<Mark> forming_marks(const FormingScene& scene, const toolpath::ToolPath& centre_path);

}  // namespace spifit::scene
