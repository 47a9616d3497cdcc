// Where the tests find the repository, their data and the programs they run: this build's
// absolute paths, defined in test_paths.cpp alone (its compile definitions). A test object then
// holds no path of its clone, so ccache serves it to every clone of the same commit (CI's fresh
// clone reuses what another build compiled); only test_paths.cpp compiles again.
//
// Outputs (each a NUL-terminated absolute path):
//   kSourceDir        the repository's root
//   kTestData         tests/data
//   kBinary           the curvefold program
//   kFakePortal       the desktop portal stand-in (tests/fake_portal.cpp)
//   kSimRuntimeJson   the simulated OpenXR runtime's manifest
//   kSimRuntimeLibrary  that runtime's shared library
// Limits: they are not string literals; join them with std::string or std::filesystem::path.
#pragma once

namespace curvefold::testing {

extern const char* const kSourceDir;
extern const char* const kTestData;
extern const char* const kBinary;
extern const char* const kFakePortal;
extern const char* const kSimRuntimeJson;
extern const char* const kSimRuntimeLibrary;

}  // namespace curvefold::testing

// The names the tests have always used.
#define CURVEFOLD_SOURCE_DIR (::curvefold::testing::kSourceDir)
#define CURVEFOLD_TEST_DATA (::curvefold::testing::kTestData)
#define CURVEFOLD_BINARY (::curvefold::testing::kBinary)
#define CURVEFOLD_FAKE_PORTAL (::curvefold::testing::kFakePortal)
#define CURVEFOLD_SIM_RUNTIME_JSON (::curvefold::testing::kSimRuntimeJson)
#define CURVEFOLD_SIM_RUNTIME_LIBRARY (::curvefold::testing::kSimRuntimeLibrary)
