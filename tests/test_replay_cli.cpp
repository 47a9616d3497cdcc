// `curvefold replay` and `curvefold record-script`, run as a user runs them: all five output files
// or none, one-line errors naming file and line, truncated recordings only when allowed.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"
#include "test_paths.hpp"

namespace fs = std::filesystem;
using curvefold::testing::CommandResult;
using curvefold::testing::slurp;

namespace {

const fs::path kRecordings = fs::path(CURVEFOLD_TEST_DATA) / "recordings";
const char* const kOutputs[] = {".curvefold.json", ".fold", ".svg", ".obj", ".folds.jsonl"};

std::size_t lineCount(const std::string& text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

class ReplayCli : public curvefold::testing::CliTest {
 protected:
  // Nothing but the captured streams: no output folder, no file, no temporary.
  void expectNothingWritten() const {
    for (const auto& entry : fs::directory_iterator(dir_)) {
      const std::string name = entry.path().filename().string();
      EXPECT_TRUE(name == ".stdout" || name == ".stderr") << "left behind: " << name;
    }
  }

  void expectAllOutputs(const fs::path& folder, const std::string& name) const {
    for (const char* extension : kOutputs)
      EXPECT_TRUE(fs::is_regular_file(folder / (name + extension))) << name + extension;
    for (const auto& entry : fs::directory_iterator(folder))
      EXPECT_NE(entry.path().filename().string().front(), '.')
          << "temporary left behind: " << entry.path();
  }
};

TEST_F(ReplayCli, WritesAllFiveOutputs) {
  const fs::path out = dir_ / "out";
  const CommandResult r =
      run("replay " + (kRecordings / "square_one_fold.jsonl").string() + " --out " + out.string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_EQ(lineCount(r.out), 1u) << r.out;
  EXPECT_NE(r.out.find("13 frames"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("1 fold,"), std::string::npos) << r.out;
  expectAllOutputs(out, "square_one_fold");

  const nlohmann::json design =
      nlohmann::json::parse(slurp(out / "square_one_fold.curvefold.json"));
  EXPECT_EQ(design["format"], "curvefold-design");
  EXPECT_EQ(design["surface"]["generator"], "square");
  EXPECT_EQ(design["folds"].size(), 1u);
  const std::string log = slurp(out / "square_one_fold.folds.jsonl");
  ASSERT_EQ(lineCount(log), 1u);
  const nlohmann::json entry = nlohmann::json::parse(log);
  EXPECT_EQ(entry["event"], "commit");
  EXPECT_EQ(entry["fold"], 1);
  EXPECT_DOUBLE_EQ(entry["t"].get<double>(), 1.2);
  EXPECT_LT(entry["triangles_before"].get<int>(), entry["triangles_after"].get<int>());
  EXPECT_LT(entry["max_edge_length_error"].get<double>(), 1e-12);

  // The design passes `check`, and a second replay overwrites with identical files.
  EXPECT_EQ(run("check " + (out / "square_one_fold.curvefold.json").string()).exitCode, 0);
  const std::string obj = slurp(out / "square_one_fold.obj");
  ASSERT_EQ(
      run("replay " + (kRecordings / "square_one_fold.jsonl").string() + " --out " + out.string())
          .exitCode,
      0);
  EXPECT_EQ(slurp(out / "square_one_fold.obj"), obj);
  expectAllOutputs(out, "square_one_fold");
}

TEST_F(ReplayCli, DefaultOutputFolderIsTheRecordingsNameInTheCurrentFolder) {
  const CommandResult r = run("replay " + (kRecordings / "square_one_fold.jsonl").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  expectAllOutputs(dir_ / "square_one_fold", "square_one_fold");
}

TEST_F(ReplayCli, BadRecordingsGiveOneLineAndNoFiles) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"nan.jsonl", "line 5: sheet.position[1]: must be a finite number"},
      {"bad_quaternion.jsonl", "line 7: sheet.orientation: is not a unit quaternion"},
      {"backwards.jsonl", "line 10: t: time goes backwards"},
      {"version3.jsonl", "line 1: unsupported version 3"},
      {"unknown_source.jsonl", "line 1: source: unknown source \"kinect\""},
      {"bad_surface.jsonl", "line 1: surface \"square\""},
      {"truncated.jsonl", "truncated at line 14"},
      {"missing.jsonl", "cannot read"}};
  for (const auto& [name, fragment] : cases) {
    const fs::path recording = kRecordings / name;
    const CommandResult r = run("replay " + recording.string());
    EXPECT_NE(r.exitCode, 0) << name;
    EXPECT_EQ(lineCount(r.err), 1u) << r.err;
    EXPECT_EQ(r.err.rfind("curvefold: error: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(recording.string()), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(fragment), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "") << name;
    expectNothingWritten();
  }
}

TEST_F(ReplayCli, TruncatedRecordingReplaysOnlyWhenAllowed) {
  const fs::path recording = kRecordings / "truncated.jsonl";
  const CommandResult refused = run("replay " + recording.string() + " --out out");
  EXPECT_NE(refused.exitCode, 0);
  expectNothingWritten();

  const CommandResult r = run("replay " + recording.string() + " --out out --allow-truncated");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(lineCount(r.err), 1u) << r.err;
  EXPECT_NE(r.err.find("warning"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("truncated at line 14"), std::string::npos) << r.err;
  expectAllOutputs(dir_ / "out", "truncated");
  // The cut-off release never happened: the drag is dropped and no fold is committed.
  EXPECT_EQ(slurp(dir_ / "out" / "truncated.folds.jsonl"), "");
}

TEST_F(ReplayCli, UnwritableOutputLeavesNothing) {
  { std::ofstream(dir_ / "blocker") << "a file where the folder should be\n"; }
  const CommandResult r =
      run("replay " + (kRecordings / "square_one_fold.jsonl").string() + " --out blocker/out");
  EXPECT_NE(r.exitCode, 0);
  EXPECT_EQ(lineCount(r.err), 1u) << r.err;
  EXPECT_NE(r.err.find("blocker/out"), std::string::npos) << r.err;
  EXPECT_EQ(slurp(dir_ / "blocker"), "a file where the folder should be\n");
}

TEST_F(ReplayCli, RecordScriptMakesARecordingThatReplays) {
  const fs::path script = dir_ / "fold.gesture.json";
  {
    std::ofstream(script) << R"({"format":"curvefold-gesture-script","version":1,"rate":30,
      "surface":{"generator":"square","parameters":{"resolution":10}},
      "gestures":[{"wait":0.2},
                  {"drag":{"grab":[0.1,0.0,0.0],"to":[0.05,0.0,0.05],"duration":0.5}}]})";
  }
  const CommandResult recorded = run("record-script " + script.string() + " -o fold.jsonl");
  ASSERT_EQ(recorded.exitCode, 0) << recorded.err;
  EXPECT_EQ(lineCount(recorded.out), 1u) << recorded.out;
  const CommandResult replayed = run("replay fold.jsonl");
  ASSERT_EQ(replayed.exitCode, 0) << replayed.err;
  expectAllOutputs(dir_ / "fold", "fold");
  EXPECT_EQ(lineCount(slurp(dir_ / "fold" / "fold.folds.jsonl")), 1u);

  const CommandResult bad = run("record-script " + (dir_ / "none.json").string() + " -o x.jsonl");
  EXPECT_NE(bad.exitCode, 0);
  EXPECT_EQ(lineCount(bad.err), 1u) << bad.err;
  EXPECT_FALSE(fs::exists(dir_ / "x.jsonl"));
}

}  // namespace
