// Symmetric folding (issue 17, 2): which symmetries each catalog surface has, refusals in one line,
// and folds whose images keep the folded mesh and its crease pattern mapping onto themselves
// (within 1e-9 of the sheet's size), each image a fold that passes every invariant.
#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "engine/geometry/creases.hpp"
#include "engine/geometry/symmetry.hpp"
#include "engine/geometry/topology.hpp"
#include "engine/geometry/validate.hpp"
#include "engine/surfaces/surfaces.hpp"

namespace curvefold {
namespace {

TEST(Symmetry, EachSurfaceSaysWhichItHas) {
  for (const SurfaceInfo& info : surfaceCatalog()) {
    const std::vector<std::string> found = symmetriesOf(makeSurface(info.name));
    std::string list;
    for (const std::string& s : found) list += s + " ";
    RecordProperty(info.name, list);
  }
  EXPECT_EQ(symmetriesOf(makeSurface("cylinder")),
            (std::vector<std::string>{"mirror:x", "mirror:y", "mirror:z", "rotational:2:x",
                                      "rotational:12:y", "rotational:2:z"}));
  // A flat sheet's own plane fixes it: no symmetry to fold by (the mesher's triangles are not
  // symmetric either).
  EXPECT_TRUE(symmetriesOf(makeSurface("square")).empty());
}

TEST(Symmetry, WhatASurfaceLacksIsRefusedInOneLine) {
  const Sheet cylinder = makeSurface("cylinder");
  EXPECT_EQ(parseSymmetry("rotational:6", cylinder).name(), "rotational:6:y");
  EXPECT_EQ(parseSymmetry("mirror:y", cylinder).name(), "mirror:y");
  for (const char* wrong :
       {"rotational:5", "rotational:7:y", "mirror:w", "rotational:x", "spiral"}) {
    try {
      parseSymmetry(wrong, cylinder);
      ADD_FAILURE() << wrong;
    } catch (const InvalidSymmetry& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
      EXPECT_NE(message.find(wrong), std::string::npos) << message;
    }
  }
}

// Every vertex of `sheet` maps onto a vertex under g, and every crease edge onto a crease edge,
// within the tolerance.
void expectMapsOntoItself(const Sheet& sheet, const Isometry& g, double tolerance) {
  auto near = [&](const glm::dvec3& p) {
    for (const glm::dvec3& q : sheet.positions)
      if (glm::distance(p, q) <= tolerance) return true;
    return false;
  };
  for (const glm::dvec3& p : sheet.positions) ASSERT_TRUE(near(g.apply(p)));
  const std::vector<CreaseEdge> creases = creaseEdges(sheet, buildEdgeTopology(sheet));
  ASSERT_FALSE(creases.empty());
  for (const CreaseEdge& c : creases) {
    const glm::dvec3 a = g.apply(sheet.positions[c.edge.a]), b = g.apply(sheet.positions[c.edge.b]);
    bool found = false;
    for (const CreaseEdge& d : creases) {
      const glm::dvec3 p = sheet.positions[d.edge.a], q = sheet.positions[d.edge.b];
      found = found || (glm::distance(a, p) <= tolerance && glm::distance(b, q) <= tolerance) ||
              (glm::distance(a, q) <= tolerance && glm::distance(b, p) <= tolerance);
    }
    ASSERT_TRUE(found);
  }
}

// A fold on a 6-fold cylinder and a mirrored cone: the images follow, each an exact reflection
// fold, and the folded mesh and its creases map onto themselves under every element.
TEST(Symmetry, AFoldsImagesKeepTheDesignSymmetric) {
  struct Case {
    const char* surface;
    const char* symmetry;
    glm::dvec3 grab, to;
    std::size_t images;
  };
  for (const Case& c : {Case{"cylinder", "rotational:6", {0.045, 0.105, 0.0}, {0.036, 0.1, 0.0}, 5},
                        Case{"cylinder", "mirror:y", {0.0, 0.105, 0.045}, {0.0, 0.095, 0.05}, 1}}) {
    SCOPED_TRACE(std::string(c.surface) + " " + c.symmetry);
    const Sheet initial = makeSurface(c.surface);
    const Symmetry symmetry = parseSymmetry(c.symmetry, initial);
    const SymmetricFolder folder(initial, symmetry);
    FoldSession session(initial);
    session.beginDragNear(c.grab);
    session.updateDrag(c.to);
    ASSERT_TRUE(session.commit());
    Sheet sheet = session.fixed();
    const SymmetricFolder::Result result =
        folder.applyImages(initial, sheet, session.folds().back());
    EXPECT_EQ(result.applied.size(), c.images);
    EXPECT_EQ(result.skipped, 0u);
    ValidationOptions options;
    validate(sheet, options);
    const double tolerance = 1e-9 * sheetSize(initial);
    for (const Isometry& g : symmetry.images()) expectMapsOntoItself(sheet, g, tolerance);
    // The records replay to the same sheet.
    std::vector<FoldRecord> folds{session.folds().back()};
    folds.insert(folds.end(), result.applied.begin(), result.applied.end());
    EXPECT_TRUE(identical(replayFolds(initial, folds), sheet));
  }
}

// A session with a symmetry (the desktop's, the headset's, a replay's): each commit brings the
// images, undo and redo take a group at once (across a keyframe), and a design opened again keeps
// its groups.
TEST(Symmetry, ASessionCommitsUndoesAndRedoesWholeGroups) {
  const Sheet initial = makeSurface("cylinder");
  FoldSession session(initial);
  session.setSymmetry(parseSymmetry("rotational:6", initial));
  const std::pair<glm::dvec3, glm::dvec3> drags[] = {{{0.045, 0.105, 0.0}, {0.036, 0.1, 0.0}},
                                                     {{0.045, -0.105, 0.0}, {0.036, -0.1, 0.0}}};
  for (const auto& [grab, to] : drags) {
    session.beginDragNear(grab);
    session.updateDrag(to);
    ASSERT_TRUE(session.commit());
  }
  ASSERT_EQ(session.foldCount(), 12u);  // past the keyframe at 8
  EXPECT_EQ(session.folds()[5].group, 1u);
  EXPECT_EQ(session.folds()[6].group, 2u);
  const Sheet both = session.fixed();
  EXPECT_TRUE(identical(replayFolds(initial, session.folds()), both));
  ASSERT_TRUE(session.undo());
  EXPECT_EQ(session.foldCount(), 6u);
  ASSERT_TRUE(session.undo());
  EXPECT_EQ(session.foldCount(), 0u);
  EXPECT_TRUE(identical(session.fixed(), initial));
  ASSERT_TRUE(session.redo());
  EXPECT_EQ(session.foldCount(), 6u);
  ASSERT_TRUE(session.redo());
  EXPECT_TRUE(identical(session.fixed(), both));
  // Opened again from its records: the same sheet, and undo still takes the group.
  FoldSession reopened(initial);
  reopened.applyRecords(session.folds());
  EXPECT_TRUE(identical(reopened.fixed(), both));
  ASSERT_TRUE(reopened.undo());
  EXPECT_EQ(reopened.foldCount(), 6u);
}

}  // namespace
}  // namespace curvefold
