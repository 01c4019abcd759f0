#pragma once
// A numerical failure in a forming engineer's words (docs/guide/running-scenes.md, "When a run
// fails"): what most likely happened to the sheet and what to change, followed by the solver's
// own account in parentheses for whoever wants it.
#include <string>

namespace spifit::scene {

// solver: the Newton or explicit solver's message ("increment from load factor 0.42 failed at the
// minimum increment 1e-05: layer stretched to a non-positive metric (det C = -42.9) (element 17
// ...)"). Unknown messages come back as they are.
std::string failure_in_words(const std::string& solver);

}  // namespace spifit::scene
