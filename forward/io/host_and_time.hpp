#pragma once
// Who and when, as spifit writes them into files that name a process (a running summary, an
// output directory's lock): the host's name and UTC times in ISO 8601.
#include <ctime>
#include <string>

namespace spifit::io {

// "2026-11-26T01:02:03Z".
std::string utc_iso(std::time_t t);
// The time of such a text; false when it is not one.
bool parse_utc_iso(const std::string& text, std::time_t* t);
// gethostname(), "" when there is none.
std::string host_name();

}  // namespace spifit::io
