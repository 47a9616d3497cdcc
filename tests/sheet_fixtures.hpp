// Small hand-built sheets and the invariant check every test runs after every fold.
#pragma once

#include <functional>

#include <gtest/gtest.h>

#include "engine/geometry/sheet.hpp"
#include "engine/geometry/topology.hpp"
#include "engine/geometry/validate.hpp"

namespace curvefold::testing {

// A flat grid of nx by ny square cells of side `cell` in the plane z = 0 (development = xy),
// keeping only the cells for which keep(i, j) holds. Each cell is two counter-clockwise triangles.
inline Sheet flatGrid(
    int nx, int ny, double cell,
    const std::function<bool(int, int)>& keep = [](int, int) { return true; }) {
  Sheet sheet;
  std::vector<VertexIndex> index((nx + 1) * (ny + 1), kNoIndex);
  auto vertex = [&](int i, int j) {
    VertexIndex& slot = index[j * (nx + 1) + i];
    if (slot == kNoIndex) {
      slot = static_cast<VertexIndex>(sheet.positions.size());
      sheet.positions.push_back({i * cell, j * cell, 0.0});
      sheet.development.push_back({i * cell, j * cell});
    }
    return slot;
  };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      if (!keep(i, j)) continue;
      const VertexIndex a = vertex(i, j), b = vertex(i + 1, j), c = vertex(i + 1, j + 1),
                        d = vertex(i, j + 1);
      sheet.triangles.push_back({a, b, c});
      sheet.triangles.push_back({a, c, d});
    }
  return sheet;
}

// The unit square as two triangles: 0=(0,0) 1=(1,0) 2=(1,1) 3=(0,1).
inline Sheet unitSquare() {
  return flatGrid(1, 1, 1.0);
}

// validate() passes and the topology (Euler characteristic, boundary loops, components) is the
// initial sheet's.
inline void expectInvariants(const Sheet& sheet, const Sheet& initial) {
  ASSERT_NO_THROW(validate(sheet)) << [&] {
    try {
      validate(sheet);
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string();
  }();
  const SheetReport now = measure(sheet), before = measure(initial);
  EXPECT_EQ(now.eulerCharacteristic, before.eulerCharacteristic);
  EXPECT_EQ(now.boundaryLoopCount, before.boundaryLoopCount);
  EXPECT_EQ(now.componentCount, before.componentCount);
  EXPECT_LE(now.maxEdgeLengthError, 1e-9 * now.size);
}

}  // namespace curvefold::testing
