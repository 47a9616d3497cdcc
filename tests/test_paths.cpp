#include "test_paths.hpp"

namespace curvefold::testing {

// Each CURVEFOLD_..._PATH is a compile definition of this file alone (tests/CMakeLists.txt).
const char* const kSourceDir = CURVEFOLD_SOURCE_DIR_PATH;
const char* const kTestData = CURVEFOLD_TEST_DATA_PATH;
const char* const kBinary = CURVEFOLD_BINARY_PATH;
const char* const kFakePortal = CURVEFOLD_FAKE_PORTAL_PATH;
const char* const kSimRuntimeJson = CURVEFOLD_SIM_RUNTIME_JSON_PATH;
const char* const kSimRuntimeLibrary = CURVEFOLD_SIM_RUNTIME_LIBRARY_PATH;

}  // namespace curvefold::testing
