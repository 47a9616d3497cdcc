// Designs saved by earlier versions keep opening as the sheets they were (issue 40, 1). The files
// in tests/data/designs were written by earlier builds of curvefold, each checked out, built and
// run as a user runs it (`curvefold new`, then `fold`; tests/data/designs/README.md says how), with
// the OBJ that build exported of each: the design built now must write that OBJ byte for byte.
// Newer files are refused in one line naming their version.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "engine/io/design_document.hpp"
#include "engine/io/obj_writer.hpp"
#include "engine/surfaces/surfaces.hpp"
#include "io_test_support.hpp"
#include "test_paths.hpp"

namespace curvefold {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using testing::ScratchDirectory;

const fs::path kDesigns = fs::path(CURVEFOLD_TEST_DATA) / "designs";

std::string bytesOf(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Every fixture: a design and the OBJ its version exported, as "<name>.curvefold.json" and
// "<name>.obj".
std::vector<fs::path> fixtures() {
  std::vector<fs::path> designs;
  for (const auto& entry : fs::directory_iterator(kDesigns))
    if (entry.path().string().ends_with(".curvefold.json")) designs.push_back(entry.path());
  std::sort(designs.begin(), designs.end());
  return designs;
}

fs::path exportedBy(const fs::path& design) {
  std::string name = design.filename().string();
  name.resize(name.size() - std::string(".curvefold.json").size());
  return design.parent_path() / (name + ".obj");
}

using DesignHistory = ScratchDirectory;

// Each design opens as the sheet its version built, folds and all: the OBJ written now is the one
// that version wrote. Among them, disks of the version before the flat sheets were meshed for
// their symmetries, whose folds' seeds lie outside today's disk.
TEST_F(DesignHistory, EveryEarlierDesignOpensAsTheSheetItsVersionBuilt) {
  const std::vector<fs::path> designs = fixtures();
  ASSERT_GE(designs.size(), 10u);
  std::set<std::string> kinds;
  for (const fs::path& path : designs) {
    SCOPED_TRACE(path.filename().string());
    const fs::path expected = exportedBy(path);
    ASSERT_TRUE(fs::exists(expected)) << expected;
    Sheet sheet;
    try {
      const Design design = loadDesign(path);
      sheet = buildSheet(design, path.string());
      if (const auto* generated = std::get_if<GeneratedSurface>(&design.surface))
        kinds.insert(generated->generator);
      else
        kinds.insert("mesh");
    } catch (const std::exception& e) {
      ADD_FAILURE() << e.what();
      continue;
    }
    const fs::path written = dir() / "now.obj";
    writeObj(sheet, written);
    EXPECT_TRUE(bytesOf(written) == bytesOf(expected)) << "differs from " << expected;
  }
  // Every kind of surface there is, and an embedded mesh (an OBJ's).
  for (const SurfaceInfo& info : surfaceCatalog()) EXPECT_TRUE(kinds.count(info.name)) << info.name;
  EXPECT_TRUE(kinds.count("mesh"));
}

// Saved again, an earlier design says which meshing made its sheet, and opens as the same sheet.
TEST_F(DesignHistory, AnEarlierDesignSavedAgainKeepsItsSheet) {
  for (const fs::path& path : fixtures()) {
    SCOPED_TRACE(path.filename().string());
    const Design design = loadDesign(path);
    const fs::path again = dir() / "again.curvefold.json";
    saveDesign(design, again);
    const json text = json::parse(bytesOf(again));
    EXPECT_EQ(text["version"], kDesignVersion);
    if (text["surface"].contains("generator")) {
      EXPECT_TRUE(text["surface"]["generator_version"].is_number_unsigned());
    }
    const fs::path written = dir() / "again.obj";
    writeObj(buildSheet(loadDesign(again), again.string()), written);
    EXPECT_TRUE(bytesOf(written) == bytesOf(exportedBy(path)));
  }
}

std::string loadError(const fs::path& path) {
  try {
    loadDesign(path);
  } catch (const DesignError& e) {
    return e.what();
  }
  return "(loaded)";
}

// A file from a newer version, or a sheet made by a newer generator, is refused in one line that
// names the version, before anything is built.
TEST_F(DesignHistory, ANewerFileIsRefusedNamingItsVersion) {
  json document = json::parse(bytesOf(kDesigns / "disk_f093487.curvefold.json"));
  const fs::path path = dir() / "newer.curvefold.json";
  document["version"] = kDesignVersion + 1;
  std::ofstream(path) << document.dump();
  EXPECT_EQ(loadError(path),
            path.string() + ": unsupported version " + std::to_string(kDesignVersion + 1) +
                ", newer than this build reads (versions 1 to " + std::to_string(kDesignVersion) +
                "): open it with a newer curvefold");
  document["version"] = kDesignVersion;
  document["surface"]["generator_version"] = latestGeneratorVersion("disk") + 1;
  std::ofstream(path) << document.dump();
  EXPECT_EQ(loadError(path),
            path.string() + ": surface.generator_version: the \"disk\" generator version " +
                std::to_string(latestGeneratorVersion("disk") + 1) +
                " is newer than this build's (" + std::to_string(latestGeneratorVersion("disk")) +
                "): open it with a newer curvefold");
  document["surface"].erase("generator_version");
  std::ofstream(path) << document.dump();
  const std::string missing = loadError(path);
  EXPECT_NE(missing.find("generator_version"), std::string::npos) << missing;
  for (const std::string& message : {missing, loadError(path)})
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

}  // namespace
}  // namespace curvefold
