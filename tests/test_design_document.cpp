// The design document: exact round trips through save, load and replay, and one clear error for
// each kind of bad input.
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <numbers>
#include <sstream>
#include <variant>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "engine/geometry/fold_session.hpp"
#include "engine/geometry/reflection.hpp"
#include "engine/io/atomic_file.hpp"
#include "engine/io/design_document.hpp"
#include "engine/io/json_reader.hpp"
#include "engine/surfaces/surfaces.hpp"
#include "io_test_support.hpp"
#include "symmetry_test_support.hpp"

namespace curvefold {
namespace {

using nlohmann::json;
using testing::ScratchDirectory;

bool sameBits(const FoldRecord& a, const FoldRecord& b) {
  auto same = [](const auto& x, const auto& y) { return std::memcmp(&x, &y, sizeof x) == 0; };
  bool seeds = a.moreSeeds.size() == b.moreSeeds.size();
  for (std::size_t i = 0; seeds && i < a.moreSeeds.size(); ++i)
    seeds = same(a.moreSeeds[i], b.moreSeeds[i]);
  return same(a.seed, b.seed) && same(a.plane.point, b.plane.point) &&
         same(a.plane.normal, b.plane.normal) && same(a.grabbed, b.grabbed) &&
         same(a.target, b.target) && a.group == b.group && seeds;
}

const SurfaceParameters kSquare = {{"size", 0.2}, {"resolution", 6}};

using DesignDocument = ScratchDirectory;

TEST_F(DesignDocument, GeneratedSurfaceRoundTripRebuildsBitForBit) {
  FoldSession session(makeSurface("square", kSquare));
  session.beginDragAtDevelopment({-0.07, 0.013});
  session.updateDrag({-0.01, 0.03, 0.06});
  ASSERT_TRUE(session.commit());
  session.beginDragAtDevelopment({0.081, -0.0733});
  session.updateDrag({0.02, -0.01, -0.045});
  ASSERT_TRUE(session.commit());
  session.beginDragAtDevelopment({0.0913, 0.0877});
  session.updateDrag({0.05 / 3.0, 0.01, 0.1 / 7.0});
  ASSERT_TRUE(session.commit());
  ASSERT_EQ(session.folds().size(), 3u);

  const Design design{GeneratedSurface{"square", kSquare}, session.folds()};
  const auto path = dir() / "square.curvefold.json";
  saveDesign(design, path);
  EXPECT_EQ(entries(), std::vector<std::string>{"square.curvefold.json"});
  const json written = json::parse(readText(path));
  EXPECT_EQ(written["format"], "curvefold-design");
  EXPECT_EQ(written["version"], 2);
  EXPECT_EQ(written["surface"]["generator_version"], 2);
  EXPECT_EQ(written["surface"]["generator"], "square");

  const Design loaded = loadDesign(path);
  const auto* surface = std::get_if<GeneratedSurface>(&loaded.surface);
  ASSERT_NE(surface, nullptr);
  EXPECT_EQ(surface->generator, "square");
  EXPECT_EQ(surface->parameters, kSquare);
  ASSERT_EQ(loaded.folds.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_TRUE(sameBits(loaded.folds[i], session.folds()[i]));

  const Sheet rebuilt = buildSheet(loaded, path.string());
  EXPECT_TRUE(identical(rebuilt, session.fixed()));
  EXPECT_TRUE(identical(rebuilt, replayFolds(makeSurface("square", kSquare), session.folds())));
  EXPECT_FALSE(identical(rebuilt, initialSheet(loaded)));
}

// Issue 17: a symmetric design keeps its symmetry, its groups and an image's more seeds (the
// image of a cap across the cylinder's slit), and rebuilds bit for bit without the symmetry.
TEST_F(DesignDocument, SymmetricGroupsAndMoreSeedsRoundTrip) {
  FoldSession session(makeSurface("cylinder"));
  ASSERT_NO_FATAL_FAILURE(testing::foldCapWhoseImageCrossesTheSlit(session));
  const Design design{GeneratedSurface{"cylinder", {}}, session.folds(), "rotational:6:y"};
  const auto path = dir() / "cylinder.curvefold.json";
  saveDesign(design, path);
  const Design loaded = loadDesign(path);
  EXPECT_EQ(loaded.symmetry, "rotational:6:y");
  ASSERT_EQ(loaded.folds.size(), 6u);
  std::size_t moreSeeds = 0;
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_TRUE(sameBits(loaded.folds[i], session.folds()[i])) << i;
    moreSeeds += loaded.folds[i].moreSeeds.size();
  }
  EXPECT_EQ(moreSeeds, 1u);
  EXPECT_TRUE(identical(buildSheet(loaded, path.string()), session.fixed()));
}

TEST_F(DesignDocument, EmbeddedMeshRoundTripKeepsEveryBitAndTag) {
  const Sheet strip = testing::testStrip();  // positions from cos/sin: full 17-digit doubles
  const glm::dvec3 p0 = strip.positions[11];
  FoldRecord fold;
  fold.seed = strip.development[11];
  fold.plane = bisectorPlane(p0, p0 + glm::dvec3(-0.013, 0.0, 0.021));
  fold.grabbed = p0;
  fold.target = p0 + glm::dvec3(-0.013, 0.0, 0.021);
  const Design design{strip, {fold}};

  const auto path = dir() / "strip.curvefold.json";
  saveDesign(design, path);
  const Design loaded = loadDesign(path);
  const auto* mesh = std::get_if<Sheet>(&loaded.surface);
  ASSERT_NE(mesh, nullptr);
  EXPECT_TRUE(identical(*mesh, strip));
  EXPECT_EQ(mesh->tags, strip.tags);
  EXPECT_TRUE(identical(initialSheet(loaded), strip));
  ASSERT_EQ(loaded.folds.size(), 1u);
  EXPECT_TRUE(sameBits(loaded.folds[0], fold));
  const Sheet rebuilt = buildSheet(loaded);
  EXPECT_TRUE(identical(rebuilt, replayFolds(strip, {fold})));
  EXPECT_FALSE(identical(rebuilt, strip));
}

TEST_F(DesignDocument, NegativeZeroAndTinyNumbersSurvive) {
  FoldRecord fold;
  fold.seed = {-0.0, 5e-324};
  fold.plane.point = {0.1, -0.0, std::nextafter(0.2, 1.0)};
  fold.plane.normal = glm::normalize(glm::dvec3(1.0, 1.0 / 3.0, -0.0));
  fold.grabbed = {std::numeric_limits<double>::max(), -1e-300, 1.0 / 3.0};
  const Design design{GeneratedSurface{"square", {}}, {fold}};
  const auto path = dir() / "numbers.curvefold.json";
  saveDesign(design, path);
  const Design loaded = loadDesign(path);
  ASSERT_EQ(loaded.folds.size(), 1u);
  EXPECT_TRUE(sameBits(loaded.folds[0], fold));
}

// --- bad documents ------------------------------------------------------------------------------

const char* const kName = "bad.curvefold.json";

json validDocument() {
  return json::parse(R"({
    "format": "curvefold-design", "version": 1,
    "surface": {"generator": "square", "parameters": {"resolution": 6}},
    "folds": [{"seed": [-0.07, 0.013], "plane": {"point": [0, 0, 0], "normal": [1, 0, 0]},
               "grabbed": [0, 0, 0], "target": [0, 0, 0]}]})");
}

json meshDocument() {
  json document = validDocument();
  document["surface"] = json::parse(R"({"mesh": {
      "positions": [[0, 0, 0], [0.1, 0, 0], [0.1, 0.1, 0], [0, 0.1, 0]],
      "development": [[0, 0], [0.1, 0], [0.1, 0.1], [0, 0.1]],
      "triangles": [[0, 1, 2], [0, 2, 3]], "slits": []}})");
  document["folds"] = json::array();
  return document;
}

// The DesignError message for a document, checked to be one line that starts with the name.
std::string errorOf(const std::string& text) {
  std::istringstream in(text);
  try {
    parseDesign(in, kName);
  } catch (const DesignError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(std::string(kName) + ": ", 0), 0u) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    return message;
  }
  ADD_FAILURE() << "no DesignError for " << text;
  return {};
}

std::string errorOf(const json& document) {
  return errorOf(document.dump());
}

std::string errorAfter(json document, const std::function<void(json&)>& change) {
  change(document);
  return errorOf(document);
}

TEST(DesignErrors, ValidTemplatesParse) {
  std::istringstream valid(validDocument().dump());
  EXPECT_EQ(parseDesign(valid, kName).folds.size(), 1u);
  std::istringstream mesh(meshDocument().dump());
  EXPECT_TRUE(std::holds_alternative<Sheet>(parseDesign(mesh, kName).surface));
}

TEST(DesignErrors, NotJsonOrTruncated) {
  EXPECT_EQ(errorOf(std::string("hello")),
            std::string(kName) +
                ": not valid JSON at byte 1 (line 1, column 1): syntax error while parsing value - "
                "invalid literal; last read: 'h'");
  EXPECT_NE(errorOf(std::string()).find("not valid JSON at byte 1 "), std::string::npos);
  const std::string text = validDocument().dump();
  const std::string cut = text.substr(0, text.find("\"normal\""));  // ends before a key
  const std::string message = errorOf(cut);
  EXPECT_NE(message.find("not valid JSON at byte " + std::to_string(cut.size() + 1) + " "),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("unexpected end of input"), std::string::npos) << message;
}

TEST(DesignErrors, NumberTooLargeForADouble) {
  std::string text = validDocument().dump();
  text.replace(text.find("-0.07"), 5, "1e400");
  EXPECT_NE(errorOf(text).find("not valid JSON: number overflow parsing '1e400'"),
            std::string::npos);
}

// Issue 13, A1: a "format" nested 100,000 deep overflowed the stack when the message dumped it.
// Messages quote at most about 60 characters of any value, keys included.
TEST(DesignErrors, DeepOrHugeValuesAreQuotedByAShortExcerpt) {
  const std::string deep = std::string(100'000, '[') + std::string(100'000, ']');
  const std::string message = errorOf(R"({"format":)" + deep + "}");
  EXPECT_EQ(message, std::string(kName) + ": not a curvefold design (format " +
                         std::string(57, '[') + "..., expected \"curvefold-design\")");
  const std::string longKey(100'000, 'k');
  const std::string keyMessage = errorAfter(validDocument(), [&](json& d) {
    d["surface"] = {{"generator", "square"}, {"parameters", {{longKey, "x"}}}};
  });
  EXPECT_LT(keyMessage.size(), 200u) << keyMessage.substr(0, 300);
  EXPECT_NE(keyMessage.find("must be a finite number"), std::string::npos) << keyMessage;
  EXPECT_EQ(jsonExcerpt(json::parse(R"({"a":[1,2,{"b":"c"}]})")), R"({"a":[1,2,{"b":"c"}]})");
  EXPECT_EQ(jsonExcerpt(json(std::string(100, 'x'))).size(), kJsonExcerptLength);
}

TEST(DesignErrors, FormatAndVersion) {
  EXPECT_NE(errorOf(json::array()).find("not a curvefold design"), std::string::npos);
  EXPECT_NE(errorAfter(validDocument(), [](json& d) { d.erase("format"); })
                .find("not a curvefold design (no \"format\")"),
            std::string::npos);
  EXPECT_NE(errorAfter(validDocument(), [](json& d) { d["format"] = "curvefold-recording"; })
                .find("format \"curvefold-recording\", expected \"curvefold-design\""),
            std::string::npos);
  EXPECT_EQ(errorAfter(validDocument(), [](json& d) { d["version"] = 3; }),
            std::string(kName) +
                ": unsupported version 3, newer than this build reads (versions 1 to 2): open it "
                "with a newer curvefold");
  EXPECT_EQ(errorAfter(validDocument(), [](json& d) { d["version"] = "1"; }),
            std::string(kName) + ": unsupported version \"1\" (this build reads versions 1 to 2)");
  EXPECT_EQ(errorAfter(validDocument(), [](json& d) { d["version"] = 0; }),
            std::string(kName) + ": unsupported version 0 (this build reads versions 1 to 2)");
  EXPECT_EQ(errorAfter(validDocument(), [](json& d) { d.erase("version"); }),
            std::string(kName) + ": missing \"version\"");
}

// Issue 40, 1: a version-2 design says which generator version made its sheet.
TEST(DesignErrors, GeneratorVersion) {
  auto version2 = [](const json& generatorVersion) {
    json d = validDocument();
    d["version"] = 2;
    d["surface"]["generator_version"] = generatorVersion;
    return d;
  };
  EXPECT_EQ(errorAfter(version2(2), [](json& d) { d["surface"].erase("generator_version"); }),
            std::string(kName) + ": surface: missing \"generator_version\"");
  EXPECT_EQ(errorOf(version2(3)),
            std::string(kName) +
                ": surface.generator_version: the \"square\" generator version 3 is newer than "
                "this build's (2): open it with a newer curvefold");
  for (const json& bad : {json(0), json(-1), json(1.5), json("2"), json(nullptr)})
    EXPECT_NE(
        errorOf(version2(bad))
            .find("surface.generator_version: must be a whole number from 1, got " + bad.dump()),
        std::string::npos)
        << bad;
}

TEST_F(DesignDocument, ASavedDesignRecordsTheGeneratorVersionThatMadeItsSheet) {
  const auto path = dir() / "d.curvefold.json";
  for (const auto& [generator, version] :
       {std::pair{"disk", 2}, std::pair{"square", 2}, std::pair{"cylinder", 1}}) {
    saveDesign(Design{GeneratedSurface{generator, {{"resolution", 8}}}, {}}, path);
    const json written = json::parse(readText(path));
    EXPECT_EQ(written["version"], 2);
    EXPECT_EQ(written["surface"]["generator_version"], version) << generator;
    EXPECT_EQ(std::get<GeneratedSurface>(loadDesign(path).surface).generatorVersion, 0);
  }
  // An older meshing stays the older meshing through save and load.
  const Design old{GeneratedSurface{"disk", {{"resolution", 8}}, 1}, {}};
  saveDesign(old, path);
  EXPECT_EQ(json::parse(readText(path))["surface"]["generator_version"], 1);
  const Design loaded = loadDesign(path);
  EXPECT_EQ(std::get<GeneratedSurface>(loaded.surface).generatorVersion, 1);
  EXPECT_EQ(initialSheet(loaded).development,
            makeSurface("disk", {{"resolution", 8}}, 1).development);
  EXPECT_NE(initialSheet(loaded).development, makeSurface("disk", {{"resolution", 8}}).development);
}

// A version-1 design does not say which meshing made a flat sheet: the one before 2026-12-04,
// unless its symmetry or its folds say it was the one after.
TEST_F(DesignDocument, AVersionOneDesignIsToldItsMeshing) {
  const auto path = dir() / "v1.curvefold.json";
  auto versionOf = [&](const json& document) {
    writeFileAtomically(path, document.dump());
    return std::get<GeneratedSurface>(loadDesign(path).surface).generatorVersion;
  };
  json plain = validDocument();
  plain["folds"] = json::array();
  EXPECT_EQ(versionOf(plain), 1);
  // The cylinder's meshing never changed: version 1 is its latest.
  plain["surface"]["generator"] = "cylinder";
  EXPECT_EQ(versionOf(plain), 0);
  // Only the newer square has its quarter turns.
  json symmetric = validDocument();
  symmetric["folds"] = json::array();
  symmetric["symmetry"] = "rotational:4:z";
  EXPECT_EQ(versionOf(symmetric), 0);
  // A disk of 8 sides (resolution 2) then, of 24 now: a seed between the two outlines fits only
  // the newer one. Its plane leaves the seed's side whole: nothing but the seed decides.
  json disk = validDocument();
  disk["surface"] = json::parse(R"({"generator": "disk", "parameters": {"resolution": 2}})");
  const double r = 0.1 * std::cos(std::numbers::pi / 24.0) * 0.999;
  const double a = std::numbers::pi / 8.0;  // the middle of an old side
  disk["folds"][0]["seed"] = {r * std::cos(a), r * std::sin(a)};
  disk["folds"][0]["plane"] = json::parse(R"({"point": [0, 0, 0], "normal": [-0.6, -0.8, 0]})");
  EXPECT_EQ(versionOf(disk), 0);
  disk["folds"][0]["seed"] = {0.5 * r * std::cos(a), 0.5 * r * std::sin(a)};
  EXPECT_EQ(versionOf(disk), 1);
}

TEST(DesignErrors, Surface) {
  EXPECT_EQ(errorAfter(validDocument(), [](json& d) { d.erase("surface"); }),
            std::string(kName) + ": missing \"surface\"");
  EXPECT_EQ(errorAfter(validDocument(), [](json& d) { d["surface"]["mesh"] = json::object(); }),
            std::string(kName) + ": surface: must hold either \"generator\" or \"mesh\"");
  EXPECT_EQ(errorAfter(validDocument(), [](json& d) { d["surface"] = json::object(); }),
            std::string(kName) + ": surface: must hold either \"generator\" or \"mesh\"");
  EXPECT_EQ(errorAfter(validDocument(), [](json& d) { d["surface"]["generator"] = 5; }),
            std::string(kName) + ": surface.generator: must be a surface name");
  EXPECT_EQ(
      errorAfter(validDocument(),
                 [](json& d) { d["surface"]["parameters"]["resolution"] = nullptr; }),
      std::string(kName) + ": surface.parameters.resolution: must be a finite number, got null");
  EXPECT_EQ(
      errorAfter(validDocument(), [](json& d) { d["surface"]["parameters"] = json::array(); }),
      std::string(kName) + ": surface.parameters: must be an object, got array");
}

TEST(DesignErrors, EmbeddedMesh) {
  EXPECT_EQ(
      errorAfter(meshDocument(), [](json& d) { d["surface"]["mesh"]["development"].erase(3); }),
      std::string(kName) + ": surface.mesh: 4 positions but 3 development points");
  EXPECT_EQ(
      errorAfter(meshDocument(), [](json& d) { d["surface"]["mesh"]["triangles"][1][2] = 7; }),
      std::string(kName) +
          ": surface.mesh.triangles[1][2]: vertex 7 does not exist (the mesh has 4 vertices)");
  for (const json& index : {json(-1), json(1.5), json("2")})
    EXPECT_EQ(
        errorAfter(meshDocument(),
                   [&](json& d) { d["surface"]["mesh"]["triangles"][0][0] = index; }),
        std::string(kName) +
            ": surface.mesh.triangles[0][0]: must be a vertex index (a non-negative integer)");
  EXPECT_EQ(
      errorAfter(meshDocument(),
                 [](json& d) { d["surface"]["mesh"]["positions"][2][1] = nullptr; }),
      std::string(kName) + ": surface.mesh.positions[2][1]: must be a finite number, got null");
  EXPECT_EQ(errorAfter(meshDocument(),
                       [](json& d) {
                         d["surface"]["mesh"]["slits"] = {{1, 1}};
                       }),
            std::string(kName) + ": surface.mesh.slits[0]: an edge needs two different vertices");
  EXPECT_EQ(errorAfter(meshDocument(), [](json& d) { d["surface"]["mesh"].erase("triangles"); }),
            std::string(kName) + ": surface.mesh: missing \"triangles\"");
  // Geometrically invalid: the 3D square is stretched, so triangles are no longer congruent.
  const std::string invalid = errorAfter(meshDocument(), [](json& d) {
    d["surface"]["mesh"]["positions"][2] = {0.3, 0.1, 0.0};
  });
  EXPECT_EQ(invalid.rfind(std::string(kName) + ": surface.mesh: ", 0), 0u) << invalid;
}

// Issue 17: a fold's symmetric group is a whole number from 1, and the symmetry a string (whether
// the surface has it is for the fold command to say).
TEST(DesignErrors, GroupsAndSymmetry) {
  const std::string group0 =
      errorAfter(validDocument(), [](json& d) { d["folds"][0]["group"] = 0; });
  EXPECT_NE(group0.find("fold 1"), std::string::npos) << group0;
  EXPECT_NE(group0.find("group"), std::string::npos) << group0;
  const std::string half =
      errorAfter(validDocument(), [](json& d) { d["folds"][0]["group"] = 1.5; });
  EXPECT_NE(half.find("group"), std::string::npos) << half;
  // Issue 29: every bad value gets the same message, and the numbering is checked: groups go
  // 1, 2, ... in the order they are made, their folds together.
  const std::string negative =
      errorAfter(validDocument(), [](json& d) { d["folds"][0]["group"] = -1; });
  EXPECT_EQ(negative,
            std::string(kName) + ": fold 1: group: must be a whole number from 1, got -1");
  EXPECT_EQ(group0, std::string(kName) + ": fold 1: group: must be a whole number from 1, got 0");
  auto threeFolds = [](std::initializer_list<int> groups) {
    json d = validDocument();
    const json fold = d["folds"][0];
    d["folds"] = json::array();
    for (int g : groups) {
      d["folds"].push_back(fold);
      if (g != 0) d["folds"].back()["group"] = g;
    }
    return d;
  };
  const std::string far = errorAfter(threeFolds({1, 1, 999}), [](json&) {});
  EXPECT_EQ(far, std::string(kName) +
                     ": fold 3: group: must be 2 or 1 (groups are numbered in the order they are "
                     "made, their folds together), got 999");
  const std::string apart = errorAfter(threeFolds({1, 2, 1}), [](json&) {});
  EXPECT_NE(apart.find("fold 3: group: must be 3 or 2"), std::string::npos) << apart;
  for (auto groups : {std::initializer_list<int>{1, 1, 2}, {0, 1, 0}, {1, 2, 2}, {0, 0, 0}}) {
    std::istringstream in(threeFolds(groups).dump());
    EXPECT_EQ(parseDesign(in, kName).folds.size(), 3u);
  }
  const std::string symmetry = errorAfter(validDocument(), [](json& d) { d["symmetry"] = 6; });
  EXPECT_NE(symmetry.find("symmetry"), std::string::npos) << symmetry;
  // more_seeds: development points, a handful.
  const std::string seedsNotArray =
      errorAfter(validDocument(), [](json& d) { d["folds"][0]["more_seeds"] = 1; });
  EXPECT_NE(seedsNotArray.find("more_seeds"), std::string::npos) << seedsNotArray;
  const std::string seedNotPoint = errorAfter(validDocument(), [](json& d) {
    d["folds"][0]["more_seeds"] = json::array({json::array({1})});
  });
  EXPECT_NE(seedNotPoint.find("more_seeds"), std::string::npos) << seedNotPoint;
  const std::string tooMany = errorAfter(validDocument(), [](json& d) {
    d["folds"][0]["more_seeds"] = json::array();
    for (std::size_t i = 0; i <= kMaxMoreSeeds; ++i)
      d["folds"][0]["more_seeds"].push_back(json::array({0.0, 0.0}));
  });
  EXPECT_NE(tooMany.find("more than 64"), std::string::npos) << tooMany;
  for (const std::string* e : {&group0, &half, &symmetry, &seedsNotArray, &seedNotPoint, &tooMany})
    EXPECT_EQ(e->find('\n'), std::string::npos) << *e;
}

TEST(DesignErrors, Folds) {
  EXPECT_EQ(errorAfter(validDocument(), [](json& d) { d.erase("folds"); }),
            std::string(kName) + ": missing \"folds\"");
  EXPECT_EQ(errorAfter(validDocument(), [](json& d) { d["folds"] = json::object(); }),
            std::string(kName) + ": folds: must be an array, got object");
  EXPECT_EQ(errorAfter(validDocument(), [](json& d) { d["folds"].push_back(3); }),
            std::string(kName) + ": fold 2: must be an object, got number");
  EXPECT_EQ(errorAfter(validDocument(), [](json& d) { d["folds"][0].erase("seed"); }),
            std::string(kName) + ": fold 1: missing \"seed\"");
  EXPECT_EQ(errorAfter(validDocument(), [](json& d) { d["folds"][0]["seed"].push_back(0.0); }),
            std::string(kName) + ": fold 1: seed: must be an array of 2 numbers, got 3 values");
  // NaN is written as null by JSON writers.
  EXPECT_EQ(errorAfter(validDocument(), [](json& d) { d["folds"][0]["seed"][1] = nullptr; }),
            std::string(kName) + ": fold 1: seed[1]: must be a finite number, got null");
  EXPECT_EQ(errorAfter(validDocument(), [](json& d) { d["folds"][0]["seed"][0] = true; }),
            std::string(kName) + ": fold 1: seed[0]: must be a finite number, got boolean");
  EXPECT_EQ(errorAfter(validDocument(), [](json& d) { d["folds"][0].erase("plane"); }),
            std::string(kName) + ": fold 1: missing \"plane\"");
  EXPECT_EQ(errorAfter(validDocument(), [](json& d) { d["folds"][0]["plane"].erase("point"); }),
            std::string(kName) + ": fold 1: plane: missing \"point\"");
  EXPECT_EQ(errorAfter(validDocument(), [](json& d) { d["folds"][0]["plane"]["normal"][0] = "x"; }),
            std::string(kName) + ": fold 1: plane.normal[0]: must be a finite number, got string");
  EXPECT_EQ(errorAfter(validDocument(),
                       [](json& d) {
                         d["folds"][0]["plane"]["normal"] = {0.0, 0.0, 0.0};
                       }),
            std::string(kName) + ": fold 1: plane.normal is zero");
  EXPECT_EQ(errorAfter(validDocument(),
                       [](json& d) {
                         d["folds"][0]["plane"]["normal"] = {2.0, 0.0, 0.0};
                       }),
            std::string(kName) + ": fold 1: plane.normal is not a unit vector (length 2)");
  EXPECT_EQ(errorAfter(validDocument(),
                       [](json& d) {
                         d["folds"][0]["target"] = {1.0, 2.0};
                       }),
            std::string(kName) + ": fold 1: target: must be an array of 3 numbers, got 2 values");
}

TEST(DesignErrors, UnknownGenerator) {
  std::istringstream in(
      R"({"format":"curvefold-design","version":1,"surface":{"generator":"nosuch"},"folds":[]})");
  const Design design = parseDesign(in, kName);
  try {
    initialSheet(design, kName);
    FAIL() << "no exception";
  } catch (const DesignError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(std::string(kName) + ": surface \"nosuch\": ", 0), 0u)
        << e.what();
  }
}

TEST(DesignErrors, SeedOutsideTheSheet) {
  FoldRecord inside;
  inside.seed = {-0.07, 0.013};
  inside.plane = bisectorPlane({-0.07, 0.013, 0.0}, {-0.01, 0.03, 0.06});
  FoldRecord outside = inside;
  outside.seed = {0.5, -1.25};
  const Design design{GeneratedSurface{"square", kSquare}, {inside, outside}};
  try {
    buildSheet(design, kName);
    FAIL() << "no exception";
  } catch (const DesignError& e) {
    EXPECT_EQ(std::string(e.what()),
              std::string(kName) + ": fold 2: seed (0.5, -1.25) lies outside the sheet");
  }
}

TEST_F(DesignDocument, SaveRefusesWhatCouldNotBeLoadedAndWritesNothing) {
  FoldRecord fold;
  fold.plane.normal = {std::nan(""), 0.0, 1.0};
  const auto path = dir() / "nan.curvefold.json";
  try {
    saveDesign({GeneratedSurface{"square", {}}, {fold}}, path);
    FAIL() << "no exception";
  } catch (const DesignError& e) {
    EXPECT_EQ(std::string(e.what()),
              "cannot save " + path.string() +
                  ": fold 1: plane.normal[0]: must be a finite number, got null");
  }
  fold.plane.normal = {0.0, 0.0, 0.5};
  EXPECT_THROW(saveDesign({GeneratedSurface{"square", {}}, {fold}}, path), DesignError);
  EXPECT_THROW(saveDesign({GeneratedSurface{"square", {{"size", INFINITY}}}, {}}, path),
               DesignError);
  EXPECT_TRUE(entries().empty());
}

TEST_F(DesignDocument, UnwritableAndUnreadablePaths) {
  const Design design{GeneratedSurface{"square", kSquare}, {}};
  EXPECT_THROW(saveDesign(design, dir() / "missing" / "a.curvefold.json"), FileError);
  EXPECT_TRUE(entries().empty());
  try {
    loadDesign(dir() / "none.curvefold.json");
    FAIL() << "no exception";
  } catch (const FileError& e) {
    EXPECT_EQ(std::string(e.what()), "cannot read " + (dir() / "none.curvefold.json").string() +
                                         ": No such file or directory");
  }
}

TEST_F(DesignDocument, TruncatedFileOnDiskNamesThePath) {
  const auto path = dir() / "cut.curvefold.json";
  const std::string text = validDocument().dump();
  writeFileAtomically(path, text.substr(0, text.size() / 2));
  try {
    loadDesign(path);
    FAIL() << "no exception";
  } catch (const DesignError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path.string() + ": not valid JSON at byte ", 0), 0u)
        << e.what();
  }
}

}  // namespace
}  // namespace curvefold
