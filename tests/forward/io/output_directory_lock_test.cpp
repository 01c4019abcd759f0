// One writer per output directory (forward/io/directory_lock.hpp): a live process's lock refuses
// another writer, --force or not, naming the holder's pid; the lock of a process that died is
// taken over and named; a released lock leaves no file; a subdirectory written for the holder
// takes no lock of its own.
#include "forward/io/output_directory.hpp"
#include "tests/support/lock_holder.hpp"
#include "tests/support/temp_files.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

namespace spifit::io {
namespace {

namespace fs = std::filesystem;

TEST(OutputDirectoryLock, ALiveWritersDirectoryIsRefusedEvenWithReplaceNamingItsPid) {
  const fs::path dir = test::fresh_temp_path("live");
  { OutputDirectory::prepare(dir.string(), false).write_file("summary.json", "{}\n"); }
  EXPECT_FALSE(fs::exists(dir / DirectoryLock::kFile));  // released with its last holder
  test::LockHolder other(dir);
  ASSERT_GT(other.pid, 0);
  for (bool replace : {false, true}) {
    try {
      OutputDirectory::prepare(dir.string(), replace);
      FAIL() << "a live writer's directory was taken";
    } catch (const OutputDirectoryError& e) {
      EXPECT_EQ(e.reason(), OutputDirectoryError::Reason::locked);
      EXPECT_NE(e.message().find("pid " + std::to_string(other.pid)), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(OutputDirectory::existing(dir.string()), OutputDirectoryError);  // nor resumed
  EXPECT_TRUE(fs::exists(dir / "summary.json"));  // and nothing was removed
  // A writer on the holder's behalf (a sweep point's job) takes no lock.
  EXPECT_NO_THROW(OutputDirectory::existing(dir.string(), OutputDirectory::Locking::none));
}

TEST(OutputDirectoryLock, TheLockOfAProcessThatDiedIsTakenOverAndNamed) {
  const fs::path dir = test::fresh_temp_path("dead");
  fs::create_directories(dir);
  test::LockHolder other(dir);
  ASSERT_GT(other.pid, 0);
  const pid_t dead = other.pid;
  other.kill();  // SIGKILL: no destructor, the lock file stays, the kernel releases the lock
  ASSERT_TRUE(fs::exists(dir / DirectoryLock::kFile));
  const OutputDirectory out = OutputDirectory::prepare(dir.string(), true);
  ASSERT_TRUE(out.lock_taken_over());
  EXPECT_EQ(out.lock_taken_over()->pid, dead);
  EXPECT_NE(out.lock_taken_over()->describe().find("pid " + std::to_string(dead)), std::string::npos);
}

TEST(OutputDirectoryLock, TheLockFileIsNeitherAForeignEntryNorInTheManifest) {
  const fs::path dir = test::fresh_temp_path("manifest");
  {
    const OutputDirectory out = OutputDirectory::prepare(dir.string(), false);
    out.write_file("force.csv", "x\n");
    out.record();
    std::ifstream m(dir / OutputDirectory::kManifest);
    std::stringstream text;
    text << m.rdbuf();
    EXPECT_EQ(text.str().find(DirectoryLock::kFile), std::string::npos) << text.str();
  }
  const OutputDirectory again = OutputDirectory::prepare(dir.string(), true);
  EXPECT_TRUE(again.kept().empty());
}

}  // namespace
}  // namespace spifit::io
