// The binary archive of checkpoints (forward/io/binary_archive.hpp): every double comes back
// bit for bit (signed zeros, subnormals, infinities, NaN payloads), and a truncated, corrupted,
// foreign or out-of-step archive is refused with a message saying why.
#include "forward/io/binary_archive.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace spifit::io {
namespace {

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

std::string error_of(const std::string& bytes, const std::string& kind = "test", std::uint32_t version = 3) {
  try {
    BinaryReader r(bytes, kind, version);
    r.section("numbers");
    (void)r.f64s();
    r.finish();
  } catch (const ArchiveError& e) {
    return e.what();
  }
  return "";
}

std::string sample_archive() {
  BinaryWriter w("test", 3);
  w.section("numbers");
  w.f64s({1.0, 2.5, -3.25});
  return w.finish();
}

TEST(BinaryArchive, RoundTripIsBitExact) {
  const std::vector<double> values = {0.0,
                                      -0.0,
                                      1.0 / 3.0,
                                      -2.718281828459045,
                                      std::numeric_limits<double>::denorm_min(),
                                      -std::numeric_limits<double>::min() / 7.0,
                                      std::numeric_limits<double>::max(),
                                      std::numeric_limits<double>::infinity(),
                                      -std::numeric_limits<double>::infinity(),
                                      std::bit_cast<double>(0x7ff8000000000123ULL),  // quiet NaN with a payload
                                      std::bit_cast<double>(0xfff0000000000001ULL)};  // signalling NaN, negative
  Eigen::VectorXd v(4);
  v << 1e-300, -1e300, 0.1, 0.2;
  BinaryWriter w("test", 3);
  w.section("numbers");
  for (double x : values) w.f64(x);
  w.f64s(values);
  w.vector(v);
  w.vec3(Eigen::Vector3d(0.1, -0.0, 7.0));
  w.vec3s({Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(-4, 5, -6)});
  w.section("misc");
  w.u32(0xdeadbeefU);
  w.i64(-1234567890123LL);
  w.boolean(true);
  w.boolean(false);
  w.string(std::string("with\0zero", 9));
  w.string("");
  const std::string bytes = w.finish();

  BinaryReader r(bytes, "test", 3);
  r.section("numbers");
  for (double x : values) EXPECT_EQ(bits(r.f64()), bits(x));
  const std::vector<double> back = r.f64s();
  ASSERT_EQ(back.size(), values.size());
  for (std::size_t i = 0; i < values.size(); ++i) EXPECT_EQ(bits(back[i]), bits(values[i])) << i;
  const Eigen::VectorXd vb = r.vector();
  ASSERT_EQ(vb.size(), 4);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(bits(vb(i)), bits(v(i)));
  const Eigen::Vector3d a = r.vec3();
  EXPECT_EQ(bits(a.y()), bits(-0.0));
  EXPECT_EQ(r.vec3s().size(), 2u);
  r.section("misc");
  EXPECT_EQ(r.u32(), 0xdeadbeefU);
  EXPECT_EQ(r.i64(), -1234567890123LL);
  EXPECT_TRUE(r.boolean());
  EXPECT_FALSE(r.boolean());
  EXPECT_EQ(r.string(), std::string("with\0zero", 9));
  EXPECT_EQ(r.string(), "");
  EXPECT_NO_THROW(r.finish());
}

TEST(BinaryArchive, LayoutIsLittleEndianWithAHeader) {
  BinaryWriter w("k", 7);
  w.u32(0x01020304U);
  const std::string b = w.finish();
  EXPECT_EQ(b.substr(0, 8), "SPIFITAR");
  // magic 8, format version 4, kind (8 + 1), kind version 4, payload 4, checksum 8
  ASSERT_EQ(b.size(), 8u + 4u + 9u + 4u + 4u + 8u);
  EXPECT_EQ(static_cast<unsigned char>(b[8]), BinaryWriter::kFormatVersion);
  EXPECT_EQ(static_cast<unsigned char>(b[25]), 0x04);
  EXPECT_EQ(static_cast<unsigned char>(b[28]), 0x01);
}

TEST(BinaryArchive, DamagedOrForeignArchivesAreRefused) {
  const std::string good = sample_archive();
  EXPECT_EQ(error_of(good), "");
  // Truncated anywhere: the checksum no longer matches (or the header is incomplete).
  for (std::size_t n : {std::size_t{0}, std::size_t{5}, std::size_t{20}, good.size() / 2, good.size() - 1}) {
    const std::string e = error_of(good.substr(0, n));
    EXPECT_FALSE(e.empty()) << n;
    if (n >= 8) {
      EXPECT_TRUE(e.find("truncated") != std::string::npos) << e;
    }
  }
  // One flipped bit in the payload.
  std::string bad = good;
  bad[bad.size() - 12] = static_cast<char>(bad[bad.size() - 12] ^ 0x10);
  EXPECT_NE(error_of(bad).find("checksum mismatch"), std::string::npos) << error_of(bad);
  // Not an archive at all.
  EXPECT_NE(error_of("hello, this is a text file with enough bytes in it").find("SPIFITAR"), std::string::npos);
  // Another kind, another layout version.
  EXPECT_NE(error_of(good, "other").find("\"test\""), std::string::npos) << error_of(good, "other");
  EXPECT_NE(error_of(good, "test", 4).find("layout version 3"), std::string::npos) << error_of(good, "test", 4);
}

// A reader may accept older layouts (cone checkpoints of layout 5 after the solver's
// stabilisation state was added in 6) and says which one it read.
TEST(BinaryArchive, AReaderAcceptsARangeOfLayoutsAndNamesIt) {
  const std::string v3 = sample_archive();  // layout 3
  EXPECT_EQ(BinaryReader(v3, "test", 4, 3).kind_version(), 3u);
  EXPECT_EQ(BinaryReader(v3, "test", 3).kind_version(), 3u);
  try {
    BinaryReader r(v3, "test", 6, 4);
    ADD_FAILURE() << "layout 3 accepted by a 4-6 reader";
  } catch (const ArchiveError& e) {
    EXPECT_NE(std::string(e.what()).find("layout version 3, this spifit reads version 4 to 6"), std::string::npos) << e.what();
  }
  EXPECT_THROW(BinaryReader(v3, "test", 2, 1), ArchiveError);  // newer than the reader
}

TEST(BinaryArchive, ReadingOutOfStepIsCaught) {
  BinaryWriter w("test", 1);
  w.section("a");
  w.f64(1.0);
  const std::string b = w.finish();
  {
    BinaryReader r(b, "test", 1);
    try {
      r.section("b");
      ADD_FAILURE() << "wrong section accepted";
    } catch (const ArchiveError& e) {
      EXPECT_NE(std::string(e.what()).find("section \"b\" expected"), std::string::npos) << e.what();
    }
  }
  {
    BinaryReader r(b, "test", 1);
    r.section("a");
    EXPECT_THROW(r.finish(), ArchiveError);  // 8 unread bytes
    (void)r.f64();
    EXPECT_THROW((void)r.f64(), ArchiveError);  // past the end
  }
  {
    BinaryReader r(b, "test", 1);
    r.section("a");
    EXPECT_THROW(r.expect_count("nodes", 5), ArchiveError);  // the double's bits are not 5
  }
}

}  // namespace
}  // namespace spifit::io
