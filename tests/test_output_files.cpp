// How outputs land (issue 13, B5, B6, B9): only regular files are replaced by rename, keeping
// their permissions; symbolic links are followed; devices and FIFOs are written in place with
// their errors reported; a set of outputs is all or none; temporaries left by killed processes are
// removed by the next write of the same target. Every node is the test's own (mknod in a scratch
// folder as root, else only the FIFO), never the machine's /dev/null.
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <future>
#include <new>
#include <string>

#include <gtest/gtest.h>

#include "engine/io/atomic_file.hpp"
#include "engine/io/output_set.hpp"
#include "io_test_support.hpp"

namespace curvefold {
namespace {

namespace fs = std::filesystem;
using OutputFiles = curvefold::testing::ScratchDirectory;

std::string contentOf(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void put(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// A process id that no process has: a child that has exited and been reaped.
pid_t deadProcessId() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ::waitpid(child, nullptr, 0);
  return child;
}

TEST_F(OutputFiles, ReplacingARegularFileKeepsItsPermissions) {
  const fs::path target = dir() / "a.txt";
  put(target, "old");
  fs::permissions(target, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  writeFileAtomically(target, std::string("new"));
  EXPECT_EQ(contentOf(target), "new");
  EXPECT_EQ(fs::status(target).permissions(),
            fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
}

TEST_F(OutputFiles, ASymbolicLinkIsFollowedAndKept) {
  fs::create_directory(dir() / "real");
  put(dir() / "real" / "a.txt", "old");
  fs::create_symlink("real/a.txt", dir() / "link.txt");
  writeFileAtomically(dir() / "link.txt", std::string("new"));
  EXPECT_TRUE(fs::is_symlink(dir() / "link.txt"));
  EXPECT_EQ(contentOf(dir() / "real" / "a.txt"), "new");
  // A dangling link makes the file it names.
  fs::create_symlink("real/b.txt", dir() / "dangling.txt");
  writeFileAtomically(dir() / "dangling.txt", std::string("made"));
  EXPECT_TRUE(fs::is_symlink(dir() / "dangling.txt"));
  EXPECT_EQ(contentOf(dir() / "real" / "b.txt"), "made");
}

TEST_F(OutputFiles, AFifoIsWrittenInPlaceNotReplaced) {
  const fs::path fifo = dir() / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  auto reader = std::async(std::launch::async, [&] { return contentOf(fifo); });
  writeFileAtomically(fifo, std::string("through the pipe"));
  EXPECT_EQ(reader.get(), "through the pipe");
  EXPECT_TRUE(fs::is_fifo(fifo));
  EXPECT_EQ(entries(), std::vector<std::string>{"pipe"});  // no temporary left
}

TEST_F(OutputFiles, DevicesAreWrittenInPlaceWithTheirErrors) {
  const fs::path null = dir() / "null", full = dir() / "full";
  if (::mknod(null.c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0 ||
      ::mknod(full.c_str(), S_IFCHR | 0666, makedev(1, 7)) != 0)
    GTEST_SKIP() << "mknod needs root (the FIFO test covers the rule without it)";
  writeFileAtomically(null, std::string("gone"));
  EXPECT_TRUE(fs::is_character_file(null));  // not replaced by a regular file
  try {
    writeFileAtomically(full, std::string(1 << 17, 'x'));
    ADD_FAILURE() << "a full device reported success";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("No space left on device"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::is_character_file(full));
  // A set of outputs writes a device last, in place.
  OutputSet outputs;
  outputs.add(dir() / "a.txt", [](const fs::path& at) { writeFileAtomically(at, "a"); });
  outputs.add(null, [](const fs::path& at) { writeFileAtomically(at, "b"); });
  outputs.write();
  EXPECT_EQ(contentOf(dir() / "a.txt"), "a");
  EXPECT_TRUE(fs::is_character_file(null));
}

TEST_F(OutputFiles, AFailingOutputLeavesEveryOtherAsItWas) {
  put(dir() / "a.svg", "old svg");
  OutputSet outputs;
  outputs.add(dir() / "a.svg", [](const fs::path& at) { writeFileAtomically(at, "new svg"); });
  outputs.add(dir() / "missing" / "a.obj",
              [](const fs::path& at) { writeFileAtomically(at, "new obj"); });
  try {
    outputs.write();
    ADD_FAILURE() << "a write into a missing folder succeeded";
  } catch (const FileError& e) {
    // Named by its target, not by its staging name.
    EXPECT_NE(std::string(e.what()).find((dir() / "missing" / "a.obj").string()), std::string::npos)
        << e.what();
    EXPECT_EQ(std::string(e.what()).find("staged"), std::string::npos) << e.what();
  }
  EXPECT_EQ(contentOf(dir() / "a.svg"), "old svg");
  EXPECT_EQ(entries(), std::vector<std::string>{"a.svg"});  // nothing staged is left
}

// Issue 29, 2: an output that names a folder fails before any other is replaced (staging it
// worked: only the rename would fail, after the outputs before it were renamed).
TEST_F(OutputFiles, AnOutputThatIsAFolderLeavesEveryOtherAsItWas) {
  put(dir() / "a.svg", "old svg");
  fs::create_directory(dir() / "adir");
  OutputSet outputs;
  outputs.add(dir() / "a.svg", [](const fs::path& at) { writeFileAtomically(at, "new svg"); });
  outputs.add(dir() / "adir", [](const fs::path& at) { writeFileAtomically(at, "new obj"); });
  try {
    outputs.write();
    ADD_FAILURE() << "a write onto a folder succeeded";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("adir"), std::string::npos) << e.what();
  }
  EXPECT_EQ(contentOf(dir() / "a.svg"), "old svg");
  EXPECT_TRUE(fs::is_directory(dir() / "adir"));
  EXPECT_EQ(entries(), (std::vector<std::string>{"a.svg", "adir"}));
}

// Issue 29, 2: a device that fails (/dev/full) is written before any file is committed, so the
// files stay as they were.
TEST_F(OutputFiles, AFailingDeviceLeavesEveryFileAsItWas) {
  if (!fs::is_character_file("/dev/full")) GTEST_SKIP() << "no /dev/full";
  put(dir() / "a.svg", "old svg");
  OutputSet outputs;
  outputs.add(dir() / "a.svg", [](const fs::path& at) { writeFileAtomically(at, "new svg"); });
  outputs.add("/dev/full", [](const fs::path& at) { writeFileAtomically(at, "new obj"); });
  EXPECT_THROW(outputs.write(), FileError);
  EXPECT_EQ(contentOf(dir() / "a.svg"), "old svg");
  EXPECT_EQ(entries(), std::vector<std::string>{"a.svg"});
}

// Issue 29, 1: running out of memory in a writer is not the file's fault: it reaches the command
// as std::bad_alloc (which says so), not as a FileError reading "std::bad_alloc".
TEST_F(OutputFiles, OutOfMemoryInAWriterIsNotAFileError) {
  put(dir() / "a.svg", "old svg");
  OutputSet outputs;
  outputs.add(dir() / "a.svg", [](const fs::path&) { throw std::bad_alloc(); });
  EXPECT_THROW(outputs.write(), std::bad_alloc);
  EXPECT_EQ(contentOf(dir() / "a.svg"), "old svg");
  EXPECT_EQ(entries(), std::vector<std::string>{"a.svg"});
}

// Issue 29, 2: two outputs naming one file (also through "." or a symbolic link) are refused before
// anything is written.
TEST_F(OutputFiles, TwoOutputsNamingOneFileAreRefused) {
  put(dir() / "a.svg", "old svg");
  fs::create_symlink(dir() / "a.svg", dir() / "link.svg");
  for (const fs::path& other : {dir() / "a.svg", dir() / "." / "a.svg", dir() / "link.svg"}) {
    OutputSet outputs;
    outputs.add(dir() / "a.svg", [](const fs::path& at) { writeFileAtomically(at, "first"); });
    outputs.add(other, [](const fs::path& at) { writeFileAtomically(at, "second"); });
    EXPECT_THROW(outputs.write(), FileError) << other;
    EXPECT_EQ(contentOf(dir() / "a.svg"), "old svg") << other;
  }
  EXPECT_TRUE(sameFile(dir() / "x" / ".." / "new.svg", dir() / "new.svg"));
  EXPECT_FALSE(sameFile(dir() / "a.svg", dir() / "b.svg"));
}

TEST_F(OutputFiles, StaleTemporariesOfTheTargetAreRemoved) {
  const std::string dead = std::to_string(deadProcessId());
  const std::string alive = std::to_string(::getpid());
  for (const std::string& name :
       {".a.txt.tmp-" + dead + "-3", ".a.txt.staged-" + dead,
        "..a.txt.staged-" + dead + ".tmp-" + dead + "-0", ".a.txt.tmp-" + alive + "-999",
        ".b.txt.tmp-" + dead + "-1", std::string(".a.txt.tmp-notapid-1")})
    put(dir() / name, "left behind");
  writeFileAtomically(dir() / "a.txt", std::string("whole"));
  // Of a.txt's, only the living process's and the one that is no temporary stay; b.txt's waits
  // for a write of b.txt.
  EXPECT_EQ(entries(),
            (std::vector<std::string>{".a.txt.tmp-" + alive + "-999", ".a.txt.tmp-notapid-1",
                                      ".b.txt.tmp-" + dead + "-1", "a.txt"}));
}

}  // namespace
}  // namespace curvefold
