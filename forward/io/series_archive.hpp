#pragma once
// A series' rows in a checkpoint (binary_archive.hpp): the row count, then each row as a counted
// vector of doubles, bit-exact. The columns are the reader's: a series is restored into one built
// with the same columns.
#include "forward/io/binary_archive.hpp"
#include "forward/io/series.hpp"

#include <string>

namespace spifit::io {

void save_series_rows(BinaryWriter& w, const Series& s);
// Replaces the rows of s. ArchiveError ("invalid <what> row count", "<what> row of another
// width") on a damaged archive or rows of another width than s's columns.
void load_series_rows(BinaryReader& r, Series* s, const std::string& what);

}  // namespace spifit::io
