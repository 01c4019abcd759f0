#pragma once
// One coefficient of a material law as the law declares it (hardening/, kinematic/): its key in
// the law's card table (also the second part of its fit and sweep name, "swift.K", "af.CX"),
// unit, valid values and a one-line description.
#include "forward/io/named_inputs.hpp"

namespace spifit::material {

struct LawCoefficient {
  const char* key;
  const char* unit;
  io::Range range;
  const char* doc;
};

}  // namespace spifit::material
