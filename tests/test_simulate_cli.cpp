// `curvefold simulate` (issue 39, 3): outputs all or none, one-line errors.
#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"

namespace curvefold::testing {
namespace {

class SimulateCli : public CliTest {};

TEST_F(SimulateCli, WritesTheSettledStateAsObjAndFoldWithItsFoldedFrame) {
  ASSERT_EQ(run("new cone --resolution 12 -o c.curvefold.json").exitCode, 0);
  const CommandResult result =
      run("simulate c.curvefold.json --percent 0:100:3 --settle --obj c.obj --fold c.fold");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_NE(result.out.find("100%: settled"), std::string::npos) << result.out;
  const nlohmann::json fold = nlohmann::json::parse(slurp(path("c.fold")));
  ASSERT_EQ(fold["file_frames"].size(), 1u);
  const auto& folded = fold["file_frames"][0]["vertices_coords"];
  ASSERT_EQ(folded.size(), fold["vertices_coords"].size());
  // The folded frame is 3D and not flat: the cone's sheet bends out of its plane.
  double zRange = 0.0;
  for (const auto& p : folded) zRange = std::max(zRange, std::abs(p[2].get<double>()));
  EXPECT_GT(zRange, 1e-3);
  EXPECT_NE(slurp(path("c.obj")).find("\nf "), std::string::npos);
}

TEST_F(SimulateCli, BadOptionsAreOneLineAndWriteNothing) {
  ASSERT_EQ(run("new square -o s.curvefold.json").exitCode, 0);
  for (const std::string options :
       {"--percent 120 --obj s.obj", "--percent nan --obj s.obj", "--percent 0:100:1 --obj s.obj",
        "--percent 50 --paper 0 --obj s.obj", "--percent 50 --glue 0,0 --obj s.obj", "--percent 50",
        "--percent 50 --obj s.obj --fold missing-folder/s.fold"}) {
    const CommandResult result = run("simulate s.curvefold.json " + options);
    EXPECT_EQ(result.exitCode, 1) << options;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1)
        << options << ": " << result.err;
    EXPECT_FALSE(fs::exists(path("s.obj"))) << options;
  }
  const CommandResult fold = run("simulate other.fold --percent 50 --obj s.obj");
  EXPECT_EQ(fold.exitCode, 1);
  EXPECT_NE(fold.err.find("other.fold"), std::string::npos) << fold.err;
}

}  // namespace
}  // namespace curvefold::testing
