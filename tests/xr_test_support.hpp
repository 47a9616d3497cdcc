// What the tests of `curvefold xr` on the simulated runtime share: the environment that serves a
// recording through it, the folds `curvefold replay` makes of a recording, and a comparison of
// JSON numbers within a tolerance.
#pragma once

#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"
#include "test_paths.hpp"

namespace curvefold::testing {

inline const std::string kExamples = std::string(CURVEFOLD_SOURCE_DIR) + "/examples/recordings/";

class XrApp : public CliTest {
 protected:
  // The environment that makes the loader use the simulated runtime serving `input`.
  std::string simulated(const std::string& input, const std::string& more = "") const {
    return "XR_RUNTIME_JSON=" + std::string(CURVEFOLD_SIM_RUNTIME_JSON) +
           " CURVEFOLD_SIM_INPUT=" + input + " CURVEFOLD_SIM_LOG=" + path("sim.log").string() +
           " " + more;
  }
  nlohmann::json load(const std::string& name) const {
    return nlohmann::json::parse(slurp(path(name)));
  }
  // The folds `curvefold replay` makes of a recording.
  nlohmann::json replayed(const std::string& recording, const std::string& name) const {
    const CommandResult result = run("replay " + recording + " --out " + path(name).string());
    EXPECT_EQ(result.exitCode, 0) << result.err;
    const std::string stem = fs::path(recording).stem().string();
    return nlohmann::json::parse(slurp(path(name) / (stem + ".curvefold.json")));
  }
};

// Every number of two JSON values within `tolerance` (float poses from the runtime against the
// recording's doubles), and the same shape.
inline void expectClose(const nlohmann::json& a, const nlohmann::json& b, double tolerance,
                        const std::string& where = "") {
  ASSERT_EQ(a.type(), b.type()) << where;
  if (a.is_number()) {
    EXPECT_NEAR(a.get<double>(), b.get<double>(), tolerance) << where;
  } else if (a.is_array()) {
    ASSERT_EQ(a.size(), b.size()) << where;
    for (std::size_t i = 0; i < a.size(); ++i)
      expectClose(a[i], b[i], tolerance, where + "[" + std::to_string(i) + "]");
  } else if (a.is_object()) {
    ASSERT_EQ(a.size(), b.size()) << where;
    for (auto it = a.begin(); it != a.end(); ++it) {
      ASSERT_TRUE(b.contains(it.key())) << where << "." << it.key();
      expectClose(it.value(), b[it.key()], tolerance, where + "." + it.key());
    }
  } else {
    EXPECT_EQ(a, b) << where;
  }
}

}  // namespace curvefold::testing
