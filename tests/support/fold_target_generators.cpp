#include "tests/support/fold_target_generators.hpp"

#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include <glm/geometric.hpp>

#include "app/session/design_check.hpp"
#include "engine/geometry/creases.hpp"
#include "engine/geometry/fold_session.hpp"
#include "engine/geometry/self_intersection.hpp"
#include "engine/geometry/symmetry.hpp"
#include "engine/geometry/topology.hpp"
#include "engine/io/obj_writer.hpp"
#include "engine/surfaces/obj_surface.hpp"
#include "engine/surfaces/surfaces.hpp"
#include "tests/support/fold_steps.hpp"

namespace curvefold::testing {
namespace {

// The vertices a recipe may grab: all, or those in the outer third from the box's centre.
std::vector<VertexIndex> grabbable(const Sheet& sheet, bool outerThird) {
  const TriangleMesh mesh = meshOf(sheet);
  glm::dvec3 lo(1e300), hi(-1e300);
  for (const glm::dvec3& p : mesh.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const glm::dvec3 centre = 0.5 * (lo + hi);
  double farthest = 0.0;
  for (const glm::dvec3& p : mesh.positions)
    farthest = std::max(farthest, glm::distance(p, centre));
  std::vector<VertexIndex> out;
  for (VertexIndex v = 0; v < sheet.vertexCount(); ++v)
    if (!outerThird || glm::distance(sheet.positions[v], centre) >= farthest * 2.0 / 3.0)
      out.push_back(v);
  return out;
}

// Whether the plane cuts a crease of `sheet` on the part the drag moves.
bool cutsEarlierCrease(const Sheet& sheet, const ReflectionPlane& plane) {
  const std::vector<CreaseEdge> creases = creaseEdges(sheet, buildEdgeTopology(sheet));
  const double tolerance = 1e-6 * sheetSize(sheet);
  for (const CreaseEdge& c : creases) {
    const double a = plane.signedDistance(sheet.positions[c.edge.a]);
    const double b = plane.signedDistance(sheet.positions[c.edge.b]);
    if ((a > tolerance && b < -tolerance) || (a < -tolerance && b > tolerance)) return true;
  }
  return false;
}

}  // namespace

const std::vector<FoldTargetRecipe>& foldTargetRecipes() {
  static const std::vector<FoldTargetRecipe> recipes = {
      {"anywhere-long", false, 0.15, 0.60, false, false},
      {"outer-short", true, 0.10, 0.35, false, false},
      {"crossing", false, 0.15, 0.60, true, false},
      {"symmetric", true, 0.10, 0.35, false, true},
  };
  return recipes;
}

TriangleMesh exportedWithoutDevelopment(const Sheet& sheet) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path();
  std::ostringstream name;
  name << "curvefold-target-" << ::getpid() << '-' << reinterpret_cast<std::uintptr_t>(&sheet)
       << ".obj";
  const std::filesystem::path path = dir / name.str();
  writeObj(sheet, path);
  std::ifstream in(path);
  std::stringstream stripped;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("vt ", 0) == 0) continue;
    // `f a/b c/d e/f` keeps its positions only: the texture indices name the lines just removed.
    if (line.rfind("f ", 0) == 0) {
      std::istringstream words(line.substr(2));
      std::string out = "f";
      for (std::string word; words >> word;) {
        out += ' ';
        out.append(word, 0, word.find('/'));
      }
      line = out;
    }
    stripped << line << '\n';
  }
  in.close();
  std::filesystem::remove(path);
  return parseObjMesh(stripped, "exported target");
}

std::optional<FoldTarget> makeFoldTarget(const FoldTargetRecipe& recipe, const std::string& surface,
                                         std::size_t folds, std::uint64_t seed) {
  FoldTarget target;
  target.initial = makeSurface(surface);
  FoldSession session(target.initial);
  std::mt19937_64 random(seed * 0x9e3779b97f4a7c15ull + 17);
  std::string symmetry;
  if (recipe.symmetric) {
    const std::vector<std::string> choices = symmetryChoices(target.initial);
    if (choices.empty()) return std::nullopt;
    symmetry = choices[static_cast<std::size_t>(unit(random) * choices.size()) % choices.size()];
    session.setSymmetry(parseSymmetry(symmetry, target.initial));
  }
  const double diagonal = boundingDiagonal(meshOf(target.initial));
  constexpr int kTries = 400;
  for (std::size_t k = 0; k < folds; ++k) {
    bool made = false;
    for (int attempt = 0; attempt < kTries && !made; ++attempt) {
      const Sheet& fixed = session.fixed();
      const std::vector<VertexIndex> candidates = grabbable(fixed, recipe.outerThird);
      const VertexIndex v = candidates[std::min<std::size_t>(
          candidates.size() - 1, static_cast<std::size_t>(unit(random) * candidates.size()))];
      const glm::dvec3 direction = uniformDirection(random);
      const double length =
          diagonal * (recipe.dragMin + (recipe.dragMax - recipe.dragMin) * unit(random));
      const glm::dvec3 grab = session.beginDragAtDevelopment(fixed.development[v]);
      session.updateDrag(grab + length * direction);
      if (!session.hasPlane() || session.lastChanges().newCreaseCount == 0 ||
          (recipe.cutEarlier && k > 0 && !cutsEarlierCrease(session.fixed(), session.plane()))) {
        session.cancel();
        continue;
      }
      // A fold that moves a few triangles is a fold still, but not one a designer makes.
      const double moved = static_cast<double>(session.lastChanges().movedVertices.size()) /
                           static_cast<double>(session.fixed().vertexCount());
      if (moved < 0.03) {
        session.cancel();
        continue;
      }
      made = commitUnlessSelfIntersecting(session);
    }
    if (!made) return std::nullopt;
  }
  target.design =
      Design(GeneratedSurface{surface, {}},
             {session.folds().begin(),
              session.folds().begin() + static_cast<std::ptrdiff_t>(session.foldCount())},
             symmetry);
  target.sheet = session.fixed();
  if (!session::checkDesign(target.design, "target", target.initial, target.sheet, false).passed())
    return std::nullopt;
  target.exported = exportedWithoutDevelopment(target.sheet);
  return target;
}

}  // namespace curvefold::testing
