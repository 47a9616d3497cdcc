#include "engine/io/design_document.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <new>
#include <sstream>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "engine/geometry/surface_point.hpp"
#include "engine/geometry/symmetry.hpp"
#include "engine/geometry/validate.hpp"
#include "engine/io/atomic_file.hpp"
#include "engine/io/input_limits.hpp"
#include "engine/io/json_reader.hpp"
#include "engine/surfaces/obj_surface.hpp"
#include "engine/surfaces/surfaces.hpp"

namespace curvefold {
namespace {

using nlohmann::json;
using nlohmann::ordered_json;

// Reads a JSON value into a design, with messages that name where the problem is.
class Reader : public JsonReader {
 public:
  using JsonReader::JsonReader;

  VertexIndex index(const json& value, std::size_t vertexCount, const std::string& where) const {
    if (!value.is_number_unsigned()) fail(where, "must be a vertex index (a non-negative integer)");
    const std::uint64_t i = value.get<std::uint64_t>();
    if (i >= vertexCount)
      fail(where, "vertex " + std::to_string(i) + " does not exist (the mesh has " +
                      std::to_string(vertexCount) + " vertices)");
    return static_cast<VertexIndex>(i);
  }

  template <std::size_t N>
  std::array<VertexIndex, N> indices(const json& value, std::size_t vertexCount,
                                     const std::string& where) const {
    if (array(value, where).size() != N)
      fail(where, "must hold " + std::to_string(N) + " vertex indices");
    std::array<VertexIndex, N> result;
    for (std::size_t i = 0; i < N; ++i) result[i] = index(value[i], vertexCount, item(where, i));
    return result;
  }

  Sheet mesh(const json& value) const {
    const std::string where = "surface.mesh";
    Sheet sheet;
    const json& positions = array(member(value, "positions", where), where + ".positions");
    sheet.positions.reserve(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i)
      sheet.positions.push_back(vector3(positions[i], item(where + ".positions", i)));
    const json& development = array(member(value, "development", where), where + ".development");
    sheet.development.reserve(development.size());
    for (std::size_t i = 0; i < development.size(); ++i)
      sheet.development.push_back(vector2(development[i], item(where + ".development", i)));
    if (sheet.development.size() != sheet.positions.size())
      fail(where, std::to_string(sheet.positions.size()) + " positions but " +
                      std::to_string(sheet.development.size()) + " development points");
    const std::size_t n = sheet.positions.size();
    const json& triangles = array(member(value, "triangles", where), where + ".triangles");
    sheet.triangles.reserve(triangles.size());
    for (std::size_t i = 0; i < triangles.size(); ++i)
      sheet.triangles.push_back(indices<3>(triangles[i], n, item(where + ".triangles", i)));
    auto readTags = [&](const char* key, EdgeKind kind) {
      const json* tags = optionalMember(value, key, where);
      if (!tags) return;
      const std::string list = where + "." + key;
      array(*tags, list);
      for (std::size_t i = 0; i < tags->size(); ++i) {
        const std::string at = item(list, i);
        const auto [a, b] = indices<2>((*tags)[i], n, at);
        if (a == b) fail(at, "an edge needs two different vertices");
        sheet.tags.push_back({Edge::of(a, b), kind});
      }
    };
    readTags("slits", EdgeKind::Slit);
    readTags("creases", EdgeKind::Crease);
    sheet.normalizeTags();
    try {
      // One tolerance for an embedded mesh, the one it was imported with (an OBJ's six digits
      // leave edge errors near 1e-7 of its size); folds are then held to what it brought.
      validate(sheet, ValidationOptions{.relativeLengthTolerance = kObjRelativeTolerance});
    } catch (const InvalidSheet& e) {
      fail(where, e.what());
    }
    return sheet;
  }

  // documentVersion: 0 for formats that embed a surface without a generator version (the latest).
  InitialSurface surface(const json& value, std::int64_t documentVersion) const {
    const std::string where = "surface";
    object(value, where);
    const bool generated = value.contains("generator");
    if (generated == value.contains("mesh"))
      fail(where, "must hold either \"generator\" or \"mesh\"");
    if (!generated) return mesh(value["mesh"]);
    GeneratedSurface surface;
    const json& generator = value["generator"];
    if (!generator.is_string() || generator.get_ref<const std::string&>().empty())
      fail(where + ".generator", "must be a surface name");
    surface.generator = generator.get<std::string>();
    if (const json* parameters = optionalMember(value, "parameters", where)) {
      object(*parameters, where + ".parameters");
      for (const auto& [key, parameter] : parameters->items())
        surface.parameters[key] = number(parameter, join(where + ".parameters", key));
    }
    if (documentVersion == 1) {
      surface.generatorVersion = 1;  // loadDesign tells which meshing (see there)
    } else if (documentVersion >= 2) {
      const std::string at = where + ".generator_version";
      const json& given = member(value, "generator_version", where);
      if (!given.is_number_unsigned() || given.get<std::uint64_t>() < 1)
        fail(at, "must be a whole number from 1, got " + jsonExcerpt(given));
      const std::uint64_t version = given.get<std::uint64_t>();
      try {
        const int latest = latestGeneratorVersion(surface.generator);
        if (version > static_cast<std::uint64_t>(latest))
          fail(at, "the \"" + surface.generator + "\" generator version " +
                       std::to_string(version) + " is newer than this build's (" +
                       std::to_string(latest) + "): open it with a newer curvefold");
        surface.generatorVersion = static_cast<int>(version) == latest ? 0 : int(version);
      } catch (const SurfaceError&) {
        // An unknown generator: initialSheet names it and the ones there are.
      }
    }
    return surface;
  }

  FoldRecord fold(const json& value, std::size_t number) const {
    const std::string where = "fold " + std::to_string(number);
    object(value, where);
    FoldRecord fold;
    fold.seed = vector2(member(value, "seed", where), where + ": seed");
    const json& plane = member(value, "plane", where);
    fold.plane.point = vector3(member(plane, "point", where + ": plane"), where + ": plane.point");
    fold.plane.normal =
        vector3(member(plane, "normal", where + ": plane"), where + ": plane.normal");
    const double length = glm::length(fold.plane.normal);
    if (length == 0.0) fail(where, "plane.normal is zero");
    if (std::abs(length - 1.0) > kUnitNormalTolerance)
      fail(where, "plane.normal is not a unit vector (length " + shortestDouble(length) + ")");
    // grabbed and target only describe the drag; the plane is what replays.
    if (const json* grabbed = optionalMember(value, "grabbed", where))
      fold.grabbed = vector3(*grabbed, where + ": grabbed");
    if (const json* target = optionalMember(value, "target", where))
      fold.target = vector3(*target, where + ": target");
    if (const json* group = optionalMember(value, "group", where)) {
      // One message for every bad value; design() checks the numbering across folds.
      if (!group->is_number_unsigned() || group->get<std::uint64_t>() < 1 ||
          group->get<std::uint64_t>() > 0xffffffffu)
        fail(where + ": group", "must be a whole number from 1, got " + jsonExcerpt(*group));
      fold.group = static_cast<std::uint32_t>(group->get<std::uint64_t>());
    }
    if (const json* more = optionalMember(value, "more_seeds", where)) {
      array(*more, where + ": more_seeds");
      // One per piece a slit cuts an image's part into: a handful at most.
      if (more->size() > kMaxMoreSeeds)
        fail(where, "more_seeds lists more than " + std::to_string(kMaxMoreSeeds) + " points");
      for (std::size_t k = 0; k < more->size(); ++k)
        fold.moreSeeds.push_back(vector2((*more)[k], item(where + ": more_seeds", k)));
    }
    return fold;
  }

  Design design(const json& document) const {
    const std::int64_t version =
        formatAndVersion(document, kDesignFormat, 1, kDesignVersion, "curvefold design");
    Design design;
    design.surface = surface(member(document, "surface", ""), version);
    const json& folds = array(member(document, "folds", ""), "folds");
    design.folds.reserve(folds.size());
    for (std::size_t i = 0; i < folds.size(); ++i) design.folds.push_back(fold(folds[i], i + 1));
    // A symmetric fold's images share its group. Groups are numbered 1, 2, ... as they are made
    // and a group's folds are consecutive, which is what undo and redo step over.
    std::uint32_t made = 0;
    for (std::size_t i = 0; i < design.folds.size(); ++i) {
      const std::uint32_t g = design.folds[i].group;
      if (g == 0) continue;
      const std::uint32_t previous = i > 0 ? design.folds[i - 1].group : 0;
      if (g != previous && g != made + 1)
        fail("fold " + std::to_string(i + 1) + ": group",
             "must be " + std::to_string(made + 1) +
                 (previous != 0 ? " or " + std::to_string(previous) : std::string()) +
                 " (groups are numbered in the order they are made, their folds together), got " +
                 std::to_string(g));
      made = std::max(made, g);
    }
    if (const json* symmetry = optionalMember(document, "symmetry", ""))
      design.symmetry = string(*symmetry, "symmetry");
    return design;
  }
};

ordered_json vectorJson(const glm::dvec2& v) {
  return {v.x, v.y};
}
ordered_json vectorJson(const glm::dvec3& v) {
  return {v.x, v.y, v.z};
}

// withVersion: a design's surface, which says which meshing made it (a generator the build does
// not know has no version to give: saving it is refused when it is read back).
ordered_json surfaceJsonOf(const InitialSurface& surface, bool withVersion) {
  if (const auto* generated = std::get_if<GeneratedSurface>(&surface)) {
    ordered_json parameters = ordered_json::object();
    for (const auto& [key, value] : generated->parameters) parameters[key] = value;
    ordered_json result = {{"generator", generated->generator}};
    if (withVersion) {
      int version = generated->generatorVersion;
      if (version == 0) {
        try {
          version = latestGeneratorVersion(generated->generator);
        } catch (const SurfaceError&) {
          version = 1;
        }
      }
      result["generator_version"] = version;
    }
    result["parameters"] = std::move(parameters);
    return result;
  }
  const Sheet& sheet = std::get<Sheet>(surface);
  ordered_json mesh = ordered_json::object();
  ordered_json& positions = mesh["positions"] = ordered_json::array();
  for (const glm::dvec3& p : sheet.positions) positions.push_back(vectorJson(p));
  ordered_json& development = mesh["development"] = ordered_json::array();
  for (const glm::dvec2& p : sheet.development) development.push_back(vectorJson(p));
  ordered_json& triangles = mesh["triangles"] = ordered_json::array();
  for (const Triangle& t : sheet.triangles) triangles.push_back({t[0], t[1], t[2]});
  ordered_json slits = ordered_json::array();
  ordered_json creases = ordered_json::array();
  for (const TaggedEdge& tag : sheet.tags)
    (tag.kind == EdgeKind::Slit ? slits : creases).push_back({tag.edge.a, tag.edge.b});
  mesh["slits"] = std::move(slits);
  if (!creases.empty()) mesh["creases"] = std::move(creases);
  return {{"mesh", std::move(mesh)}};
}

ordered_json foldJson(const FoldRecord& fold) {
  ordered_json value = {
      {"seed", vectorJson(fold.seed)},
      {"plane",
       {{"point", vectorJson(fold.plane.point)}, {"normal", vectorJson(fold.plane.normal)}}},
      {"grabbed", vectorJson(fold.grabbed)},
      {"target", vectorJson(fold.target)}};
  if (fold.group != 0) value["group"] = fold.group;
  if (!fold.moreSeeds.empty()) {
    ordered_json more = ordered_json::array();
    for (const glm::dvec2& p : fold.moreSeeds) more.push_back(vectorJson(p));
    value["more_seeds"] = std::move(more);
  }
  return value;
}

// The flat sheets' meshing changed from generator version 1 to 2 (2026-12-04); a version-1 design
// does not say which made it (see loadDesign). Its generator version is read as 1 until now.
void tellLegacyMeshing(Design& design, std::string_view name) {
  auto* generated = std::get_if<GeneratedSurface>(&design.surface);
  if (!generated || generated->generatorVersion != 1) return;
  int latest = 1;
  try {
    latest = latestGeneratorVersion(generated->generator);
  } catch (const SurfaceError&) {
    return;  // initialSheet names the unknown generator
  }
  // Generators that never changed: version 1 is their latest.
  if (latest == 1) {
    generated->generatorVersion = 0;
    return;
  }
  Design newer = design;
  std::get<GeneratedSurface>(newer.surface).generatorVersion = 2 == latest ? 0 : 2;
  auto fits = [&](const Design& candidate) {
    try {
      if (!candidate.symmetry.empty())
        parseSymmetry(candidate.symmetry, initialSheet(candidate, name));
      buildSheet(candidate, name);
      return true;
    } catch (const DesignError&) {
      return false;
    } catch (const InvalidSymmetry&) {
      return false;
    }
  };
  if (!fits(design) && fits(newer)) design = std::move(newer);
}

Design parseText(const std::string& text, std::string_view name) {
  if (text.size() > kMaxDesignBytes)
    throw DesignError(tooLarge(name, text.size(), kMaxDesignBytes, "design"));
  try {
    // Members a design does not have are skipped while parsing, never built: an unknown array of
    // millions of elements costs no memory (and cannot exhaust it while being destroyed).
    static const std::array<std::string_view, 5> kKnown = {"format", "version", "surface", "folds",
                                                           "symmetry"};
    Design design =
        Reader(std::string(name))
            .design(parseJsonText(text, name, [](int depth, std::string_view key) {
              return depth != 1 || std::find(kKnown.begin(), kKnown.end(), key) != kKnown.end();
            }));
    return design;
  } catch (const JsonReadError& e) {
    throw DesignError(e.what());
  } catch (const std::bad_alloc&) {
    throw DesignError(std::string(name) + ": out of memory reading it (" +
                      std::to_string(text.size()) + " bytes)");
  }
}

}  // namespace

nlohmann::ordered_json initialSurfaceJson(const InitialSurface& surface) {
  return surfaceJsonOf(surface, false);
}

InitialSurface parseInitialSurface(const nlohmann::json& value, std::string_view nameForErrors) {
  try {
    return Reader(std::string(nameForErrors)).surface(value, 0);
  } catch (const JsonReadError& e) {
    throw DesignError(e.what());
  }
}

Sheet initialSheet(const Design& design, std::string_view nameForErrors) {
  if (const auto* sheet = std::get_if<Sheet>(&design.surface)) return *sheet;
  const auto& generated = std::get<GeneratedSurface>(design.surface);
  try {
    return makeSurface(generated.generator, generated.parameters, generated.generatorVersion);
  } catch (const std::bad_alloc&) {
    throw;  // not the surface's fault: the command says what ran out
  } catch (const std::exception& e) {
    throw DesignError(std::string(nameForErrors) + ": surface \"" + generated.generator +
                      "\": " + e.what());
  }
}

Sheet buildSheet(const Design& design, std::string_view nameForErrors) {
  Sheet sheet = initialSheet(design, nameForErrors);
  for (std::size_t i = 0; i < design.folds.size(); ++i) {
    const FoldRecord& fold = design.folds[i];
    try {
      sheet = applyFold(sheet, fold);
    } catch (const InvalidSheet& e) {
      const std::string where = std::string(nameForErrors) + ": fold " + std::to_string(i + 1);
      // Same snap distance as a grab, so a seed on the outline still counts as inside.
      const double tolerance = kRelativeGrabSnap * sheetSize(sheet);
      if (!locateDevelopmentPoint(sheet, fold.seed, tolerance))
        throw DesignError(where + ": seed (" + shortestDouble(fold.seed.x) + ", " +
                          shortestDouble(fold.seed.y) + ") lies outside the sheet");
      throw DesignError(where + ": " + e.what());
    }
  }
  return sheet;
}

std::string designText(const Design& design) {
  const ordered_json surface = surfaceJsonOf(design.surface, true);
  std::vector<ordered_json> folds;
  for (const FoldRecord& fold : design.folds) folds.push_back(foldJson(fold));

  // One fold per line keeps the document readable and its diffs small.
  std::string text =
      "{\n  \"format\": " + json(kDesignFormat).dump() +
      ",\n  \"version\": " + std::to_string(kDesignVersion) +
      ",\n  \"surface\": " + surface.dump() +
      (design.symmetry.empty() ? std::string()
                               : ",\n  \"symmetry\": " + json(design.symmetry).dump()) +
      ",\n  \"folds\": [";
  for (std::size_t i = 0; i < folds.size(); ++i)
    text += (i == 0 ? "\n    " : ",\n    ") + folds[i].dump();
  text += folds.empty() ? "]\n}\n" : "\n  ]\n}\n";
  return text;
}

void saveDesign(const Design& design, const std::filesystem::path& path) {
  const std::string name = path.string();
  const std::string text = designText(design);
  // Refuse what could not be loaded back (nlohmann writes NaN as null) before touching the file.
  try {
    parseText(text, name);
  } catch (const DesignError& e) {
    throw DesignError(std::string("cannot save ") + e.what());
  }
  writeFileAtomically(path, text);
}

Design loadDesign(const std::filesystem::path& path) {
  Design design = parseText(readWholeFile(path, kMaxDesignBytes, "design"), path.string());
  tellLegacyMeshing(design, path.string());
  return design;
}

Design parseDesign(std::istream& in, std::string_view nameForErrors) {
  std::string text;
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxDesignBytes)
      throw DesignError(tooLarge(nameForErrors, 0, kMaxDesignBytes, "design"));
  }
  if (in.bad()) throw FileError("cannot read " + std::string(nameForErrors));
  return parseText(text, nameForErrors);
}

}  // namespace curvefold
