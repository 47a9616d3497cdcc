// Running the `curvefold` binary as a user does, for the command-line tests: each test gets its
// own scratch folder, and commands run there with their output captured.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "test_paths.hpp"

namespace curvefold::testing {

namespace fs = std::filesystem;

struct CommandResult {
  int exitCode = -1;
  std::string out;
  std::string err;
};

inline std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

class CliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("curvefold-" + std::string(info->test_suite_name()) + "-" +
                                        info->name() + "-" + std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    fs::remove_all(dir_);
    fs::remove_all(cacheDir());
  }

  // The folded-sheet cache of this test's commands, beside (not in) the scratch folder.
  fs::path cacheDir() const { return fs::path(dir_.string() + "-cache"); }

  fs::path path(const std::string& name) const { return dir_ / name; }

  // Runs `curvefold ARGUMENTS` in the scratch folder (so default output folders land there), with
  // `environment` ("NAME=value ...") in front.
  CommandResult run(const std::string& arguments, const std::string& environment = "") const {
    const fs::path out = dir_ / ".stdout", err = dir_ / ".stderr";
    const std::string command = "cd " + dir_.string() +
                                " && export CURVEFOLD_CACHE_DIR=" + cacheDir().string() + " && " +
                                environment + " " + CURVEFOLD_BINARY + " " + arguments + " >" +
                                out.string() + " 2>" + err.string();
    const int status = std::system(command.c_str());
    CommandResult result;
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.out = slurp(out);
    result.err = slurp(err);
    return result;
  }

  // A failed command: non-zero exit, exactly one line on stderr naming the problem, and no file
  // at `output` (nor a temporary next to it).
  void expectFailure(const std::string& arguments, const std::string& fragment,
                     const fs::path& output) const {
    const CommandResult r = run(arguments);
    EXPECT_NE(r.exitCode, 0) << arguments;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(fragment), std::string::npos) << "stderr: " << r.err;
    EXPECT_FALSE(fs::exists(output)) << output;
    for (const auto& entry : fs::directory_iterator(dir_)) {
      const std::string name = entry.path().filename().string();
      EXPECT_TRUE(name.front() == '.' || name.find(".tmp") == std::string::npos)
          << "temporary left behind: " << name;
    }
  }

  fs::path dir_;
};

}  // namespace curvefold::testing
