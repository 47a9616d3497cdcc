// `curvefold fit` and `curvefold distance` as a user runs them (issue 27): a target made with the
// command line is fitted, the result checks and measures, and bad input is one line with nothing
// written.
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"

namespace fs = std::filesystem;
using curvefold::testing::CommandResult;
using curvefold::testing::slurp;

namespace {

class FitCli : public curvefold::testing::CliTest {
 protected:
  // A coarse cylinder folded once, written as a plain OBJ (its `vt` dropped: a target is any
  // mesh).
  std::string makeTarget() const {
    const std::string design = path("made.curvefold.json").string();
    EXPECT_EQ(run("new cylinder --resolution 20 -o " + design).exitCode, 0);
    const CommandResult fold =
        run("fold " + design + " --vertex-near 0.045,0.1,0 --to 0,0.06,0 -o " + design);
    EXPECT_EQ(fold.exitCode, 0) << fold.err;
    EXPECT_EQ(run("export " + design + " --obj " + path("with-vt.obj").string()).exitCode, 0);
    std::ifstream in(path("with-vt.obj"));
    std::ofstream out(path("target.obj"));
    for (std::string line; std::getline(in, line);) {
      if (line.rfind("vt ", 0) == 0) continue;
      if (line.rfind("f ", 0) == 0) {
        // "f a/b c/d e/f" -> "f a c e"
        std::istringstream corners(line.substr(2));
        out << "f";
        for (std::string corner; corners >> corner;)
          out << ' ' << corner.substr(0, corner.find('/'));
        out << '\n';
        continue;
      }
      out << line << '\n';
    }
    return path("target.obj").string();
  }

  // The Hausdorff distance `distance` prints, relative to B's diagonal (a fraction).
  static double relativeHausdorff(const std::string& out) {
    const std::string key = "Hausdorff (two-sided): ";
    const std::size_t at = out.find(key);
    EXPECT_NE(at, std::string::npos) << out;
    const std::size_t open = out.find('(', at + key.size());
    return std::stod(out.substr(open + 1)) / 100.0;
  }
};

TEST_F(FitCli, FitsATargetIntoADesignThatChecksAndMeasures) {
  const std::string target = makeTarget();
  const std::string design = path("fitted.curvefold.json").string();
  const std::string log = path("fitted.folds.jsonl").string();
  const CommandResult fit =
      run("fit " + target + " --from cylinder --resolution 20 --folds 3 --time 60 -o " + design +
          " --log " + log);
  ASSERT_EQ(fit.exitCode, 0) << fit.err;
  EXPECT_NE(fit.out.find("start: Hausdorff"), std::string::npos) << fit.out;
  EXPECT_NE(fit.out.find("fold 1"), std::string::npos) << fit.out;
  EXPECT_NE(fit.out.find("wrote " + design), std::string::npos) << fit.out;
  const CommandResult check = run("check " + design);
  EXPECT_EQ(check.exitCode, 0) << check.out;
  const CommandResult distance = run("distance " + design + " " + target);
  ASSERT_EQ(distance.exitCode, 0) << distance.err;
  EXPECT_LE(relativeHausdorff(distance.out), 0.01) << distance.out;
  // One log line per fold kept, with its distances.
  std::istringstream lines(slurp(log));
  std::size_t count = 0;
  for (std::string line; std::getline(lines, line); ++count) {
    const nlohmann::json entry = nlohmann::json::parse(line);
    EXPECT_EQ(entry["event"], "commit");
    EXPECT_LE(entry["hausdorff_relative"].get<double>(), 1.0);
    EXPECT_GT(entry["chamfer"].get<double>(), -1.0);
  }
  const nlohmann::json saved = nlohmann::json::parse(slurp(design));
  EXPECT_EQ(saved["folds"].size(), count);
  EXPECT_GE(count, 1u);
}

TEST_F(FitCli, TheSameSeedFitsTheSameDesign) {
  const std::string target = makeTarget();
  const std::string a = path("a.curvefold.json").string(), b = path("b.curvefold.json").string();
  ASSERT_EQ(
      run("fit " + target + " --from cylinder --resolution 20 --folds 2 --seed 5 -o " + a).exitCode,
      0);
  ASSERT_EQ(
      run("fit " + target + " --from cylinder --resolution 20 --folds 2 --seed 5 -o " + b).exitCode,
      0);
  EXPECT_EQ(slurp(a), slurp(b));
}

TEST_F(FitCli, BadTargetsAndOptionsAreOneLineAndWriteNothing) {
  const std::string target = makeTarget();
  const fs::path out = path("x.curvefold.json");
  const std::string o = " -o " + out.string();
  auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(path(name)) << text;
    return path(name).string();
  };
  expectFailure("fit " + path("missing.obj").string() + " --from cylinder" + o, "missing.obj", out);
  expectFailure("fit " + write("empty.obj", "") + " --from cylinder" + o, "no faces", out);
  expectFailure("fit " + write("line.obj", "v 0 0 0\nv 0.1 0 0\nv 0.2 0 0\nf 1 2 3\n") +
                    " --from cylinder" + o,
                "degenerate", out);
  expectFailure(
      "fit " + write("nan.obj", "v 0 0 nan\nv 1 0 0\nv 0 1 0\nf 1 2 3\n") + " --from cylinder" + o,
      "nan.obj", out);
  // Far away, and in millimetres.
  {
    std::ifstream in(target);
    std::ofstream far(path("far.obj")), mm(path("mm.obj"));
    for (std::string line; std::getline(in, line);) {
      if (line.rfind("v ", 0) == 0) {
        std::istringstream v(line.substr(2));
        double x, y, z;
        v >> x >> y >> z;
        far << "v " << x + 500.0 << ' ' << y << ' ' << z << '\n';
        mm << "v " << 1000 * x << ' ' << 1000 * y << ' ' << 1000 * z << '\n';
      } else {
        far << line << '\n';
        mm << line << '\n';
      }
    }
  }
  expectFailure("fit " + path("far.obj").string() + " --from cylinder" + o, "sheet's frame", out);
  expectFailure("fit " + path("mm.obj").string() + " --from cylinder" + o, "units", out);
  expectFailure("fit " + target + " --from cylinder --folds 0" + o, "--folds", out);
  expectFailure("fit " + target + " --from cylinder --time 0" + o, "--time", out);
  expectFailure("fit " + target + " --from cylinder --time nan" + o, "--time", out);
  expectFailure("fit " + target + " --from origami_crane" + o, "origami_crane", out);
  expectFailure("fit " + target + " --from cylinder --symmetry rotational:7:x" + o, "rotational",
                out);
  expectFailure("fit " + target + " --from cylinder --radius -1" + o, "radius", out);

  // The studio's --target (design and xr) is read and checked first: one line, and no autosave,
  // window or runtime.
  const fs::path autosave = path("studio.curvefold.json");
  const std::string a = " --autosave " + autosave.string();
  for (const std::string command : {"design", "xr"}) {
    expectFailure(command + " cylinder --target " + path("missing.obj").string() + a, "missing.obj",
                  autosave);
    expectFailure(command + " cylinder --target " + path("empty.obj").string() + a, "no faces",
                  autosave);
    expectFailure(command + " cylinder --target " + path("far.obj").string() + a, "sheet's frame",
                  autosave);
    expectFailure(command + " cylinder --target " + path("mm.obj").string() + a, "units", autosave);
  }
  expectFailure("fit " + target + " --from cylinder --wobble 3" + o, "--wobble", out);
  for (const char* seed : {"abc", "-1", "18446744073709551616", "0x10", "\"\""})
    expectFailure("fit " + target + " --from cylinder --seed " + seed + o, "--seed", out);
  // An output that cannot be written is refused before the search, and nothing is written.
  const CommandResult log =
      run("fit " + target + " --from cylinder --log " + path("none/x.jsonl").string() + o);
  EXPECT_NE(log.exitCode, 0);
  EXPECT_EQ(std::count(log.err.begin(), log.err.end(), '\n'), 1) << log.err;
  EXPECT_NE(log.err.find("none/x.jsonl"), std::string::npos) << log.err;
  EXPECT_EQ(log.out.find("start:"), std::string::npos) << "searched first: " << log.out;
  EXPECT_FALSE(fs::exists(out));
  expectFailure("fit " + target + " --from cylinder -o " + dir_.string(), "folder", dir_ / "x");
}

TEST_F(FitCli, DistanceMeasuresDesignsAndObjs) {
  const std::string square = path("square.curvefold.json").string();
  ASSERT_EQ(run("new square --resolution 4 -o " + square).exitCode, 0);
  // The same square 1 cm up.
  std::ofstream(path("up.obj"))
      << "v -0.1 -0.1 0.01\nv 0.1 -0.1 0.01\nv 0.1 0.1 0.01\nv -0.1 0.1 0.01\n"
         "f 1 2 3\nf 1 3 4\n";
  const CommandResult r = run("distance " + square + " " + path("up.obj").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("Hausdorff (two-sided): 10 mm"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Chamfer (mean two-sided): 10 mm"), std::string::npos) << r.out;
  const CommandResult bad = run("distance " + square + " " + path("missing.obj").string());
  EXPECT_NE(bad.exitCode, 0);
  EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
  EXPECT_NE(bad.err.find("missing.obj"), std::string::npos) << bad.err;
  for (const char* seed : {"abc", "-1", "18446744073709551616"}) {
    const CommandResult r = run("distance " + square + " " + square + " --seed " + seed);
    EXPECT_NE(r.exitCode, 0) << seed;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("--seed"), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
  const CommandResult few = run("distance " + square + " " + square + " --samples 3");
  EXPECT_NE(few.exitCode, 0);
  EXPECT_NE(few.err.find("--samples"), std::string::npos) << few.err;
}

}  // namespace
