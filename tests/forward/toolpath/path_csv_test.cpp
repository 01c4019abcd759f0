// CSV tool paths: header with units, optional feed column, comments, BOM, and the errors with
// their line numbers.
#include "forward/toolpath/path_csv.hpp"

#include "forward/io/input_error.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

using namespace spifit::toolpath;
using spifit::io::InputError;
namespace fs = std::filesystem;

namespace {

// Writes text to a fresh temporary file; removed when the object goes.
struct TempCsv {
  fs::path path;
  explicit TempCsv(const std::string& text) {
    static int counter = 0;
    path = fs::temp_directory_path() /
           ("spifit_path_csv_" + std::to_string(::getpid()) + "_" + std::to_string(counter++) + ".csv");
    std::ofstream(path, std::ios::binary) << text;
  }
  ~TempCsv() { fs::remove(path); }
  std::string str() const { return path.string(); }
};

InputError read_error(const std::string& text) {
  const TempCsv f(text);
  try {
    read_path_csv(f.str(), 7.0);
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), f.str());
    return e;
  }
  ADD_FAILURE() << "no InputError for:\n" << text;
  return InputError("", "", "", "");
}

}  // namespace

TEST(PathCsv, HeaderWithUnitsAndFeedColumn) {
  const TempCsv f(
      "# line test pass\n"
      "X [mm], Y [mm], Z [mm], Feed [mm/s]\n"
      "-50, 0, -5, 0\n"
      "\n"
      "# the pass\n"
      "50, 0, -5, 10\n"
      "50, 0, -10, \n");  // empty feed: default
  const ToolPath p = read_path_csv(f.str(), 4.0);
  const auto& w = p.waypoints();
  ASSERT_EQ(w.size(), 3u);
  EXPECT_EQ(w[0].position, Eigen::Vector3d(-50, 0, -5));
  EXPECT_EQ(w[1].position, Eigen::Vector3d(50, 0, -5));
  EXPECT_EQ(w[2].position, Eigen::Vector3d(50, 0, -10));
  EXPECT_EQ(w[0].feed, 0.0);
  EXPECT_EQ(w[1].feed, 10.0);
  EXPECT_EQ(w[2].feed, 4.0);
  EXPECT_EQ(w[0].source_line, 3);
  EXPECT_EQ(w[1].source_line, 6);
  EXPECT_EQ(w[2].source_line, 7);
  EXPECT_NEAR(p.length(), 105.0, 1e-12);
  EXPECT_NEAR(p.duration(), 100.0 / 10.0 + 5.0 / 4.0, 1e-12);
}

TEST(PathCsv, FeedColumnOptionalAnyOrderBomAndCrlf) {
  const TempCsv f("\xEF\xBB\xBFz,x,y\r\n1,2,3\r\n1,5,7\r\n");
  const ToolPath p = read_path_csv(f.str(), 2.5);
  ASSERT_EQ(p.waypoints().size(), 2u);
  EXPECT_EQ(p.waypoints()[0].position, Eigen::Vector3d(2, 3, 1));
  EXPECT_EQ(p.waypoints()[1].position, Eigen::Vector3d(5, 7, 1));
  EXPECT_EQ(p.waypoints()[1].feed, 2.5);
  EXPECT_NEAR(p.duration(), 5.0 / 2.5, 1e-12);
  // A row may leave out a last feed column; numbers may use exponents and '+'.
  const TempCsv g("x,y,z,feed\n0,0,0,1\n+1e1,0,0\n");
  const ToolPath q = read_path_csv(g.str(), 2.0);
  EXPECT_EQ(q.waypoints()[1].position, Eigen::Vector3d(10, 0, 0));
  EXPECT_EQ(q.waypoints()[1].feed, 2.0);
}

TEST(PathCsv, MissingColumn) {
  const InputError e = read_error("# no z\nx,y,feed\n0,0,1\n1,0,1\n");
  EXPECT_EQ(e.key(), "line 2");
  EXPECT_NE(e.message().find("missing column 'z'"), std::string::npos) << e.what();
}

TEST(PathCsv, UnknownOrRepeatedColumnAndBadUnit) {
  const InputError e = read_error("x,y,z,t [s]\n0,0,0,0\n1,0,0,1\n");
  EXPECT_EQ(e.key(), "line 1");
  EXPECT_EQ(e.value(), "t [s]");
  EXPECT_NE(e.message().find("unknown column"), std::string::npos) << e.what();
  EXPECT_EQ(read_error("x,y,z,X\n").value(), "X");
  EXPECT_EQ(read_error("x [in],y,z\n").value(), "x [in]");
  EXPECT_EQ(read_error("x,y,z,feed [mm/min]\n").value(), "feed [mm/min]");
}

TEST(PathCsv, NonNumericValue) {
  const InputError e = read_error("x,y,z\n0,0,0\n\n1,abc,0\n");
  EXPECT_EQ(e.key(), "line 4");
  EXPECT_EQ(e.value(), "abc");
  EXPECT_NE(e.message().find("column 'y'"), std::string::npos) << e.what();
  EXPECT_EQ(read_error("x,y,z\n0,0,0\n1,2,3x\n").value(), "3x");
  EXPECT_EQ(read_error("x,y,z\n0,0,0\n1,,3\n").key(), "line 3");
  EXPECT_EQ(read_error("x,y,z,feed\n0,0,0,1\n1,2,3,-1\n").value(), "-1");
  EXPECT_EQ(read_error("x,y,z\n0,0,0\n1,nan,3\n").value(), "nan");
}

TEST(PathCsv, WrongColumnCount) {
  const InputError e = read_error("x [mm],y [mm],z [mm]\n0,0,0\n1,2,3,4\n");
  EXPECT_EQ(e.key(), "line 3");
  EXPECT_NE(e.message().find("expected 3 values"), std::string::npos) << e.what();
  EXPECT_NE(e.message().find("x [mm],y [mm],z [mm]"), std::string::npos) << e.what();
  EXPECT_EQ(read_error("x,y,z\n0,0,0\n1,2\n").key(), "line 3");
}

TEST(PathCsv, TooFewPointsNoHeaderMissingFile) {
  const InputError e = read_error("x,y,z\n0,0,0\n# end\n");
  EXPECT_EQ(e.key(), "line 3");
  EXPECT_NE(e.message().find("at least 2 points"), std::string::npos) << e.what();
  EXPECT_NE(read_error("# only comments\n").message().find("no header"), std::string::npos);
  EXPECT_EQ(read_error("").key(), "line 1");
  try {
    read_path_csv("/nonexistent/spifit/path.csv", 1.0);
    FAIL() << "no error for a missing file";
  } catch (const InputError& err) {
    EXPECT_EQ(err.message(), "cannot read file");
  }
}
