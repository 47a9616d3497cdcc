// Shared pieces of the fuzz targets: a sheet built from fuzzed bytes, fuzzed folds on it, and the
// invariant check that turns a broken sheet into a crash libFuzzer reports.
#pragma once

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <fuzzer/FuzzedDataProvider.h>

#include "engine/geometry/fold_session.hpp"
#include "engine/geometry/validate.hpp"
#include "engine/surfaces/surfaces.hpp"

namespace curvefold::fuzz {

[[noreturn]] inline void fail(const std::string& what) {
  std::fprintf(stderr, "invariant broken: %s\n", what.c_str());
  std::abort();
}

// A small initial surface of any kind, with fuzzed (valid or not) parameters. Returns false when
// the generator refused them, which is the right answer to bad parameters, and for a sheet past
// kFuzzedTriangles: a parameter in range can still refine the mesh (a star of 116,790 triangles
// at resolution 14), and every step of a fold on it is validated, 66 s of CPU for one 64-byte
// input under the sanitizers: libFuzzer's timeout, not a bug. Large sheets are the suite's and
// the benchmarks' (bench_drag: 1M triangles).
constexpr std::size_t kFuzzedTriangles = 5000;
inline bool fuzzedSurface(FuzzedDataProvider& data, Sheet& sheet) {
  const auto& catalog = surfaceCatalog();
  const SurfaceInfo& info =
      catalog[data.ConsumeIntegralInRange<std::size_t>(0, catalog.size() - 1)];
  SurfaceParameters parameters;
  for (const SurfaceParameter& p : info.parameters) {
    if (!data.ConsumeBool()) continue;
    // Mostly in range, sometimes anything (NaN, huge, negative).
    const double high = std::max(p.min, std::min(p.max, 1.0));  // small sheets fuzz faster
    parameters[p.name] = data.ConsumeBool() ? data.ConsumeFloatingPointInRange(p.min, high)
                                            : data.ConsumeFloatingPoint<double>();
  }
  parameters["resolution"] = data.ConsumeIntegralInRange(1, 14);
  try {
    sheet = makeSurface(info.name, parameters);
    return sheet.triangleCount() <= kFuzzedTriangles;
  } catch (const SurfaceError&) {
    return false;
  }
}

// validate() plus the initial topology: what every fold must keep.
inline void checkInvariants(const Sheet& sheet, const SheetReport& initial) {
  const SheetReport now = measure(sheet);
  if (!now.firstProblem.empty()) fail(now.firstProblem);
  if (now.eulerCharacteristic != initial.eulerCharacteristic) fail("Euler characteristic");
  if (now.boundaryLoopCount != initial.boundaryLoopCount) fail("boundary loops");
  if (now.maxEdgeLengthError > 1e-9 * now.size) fail("isometry");
}

}  // namespace curvefold::fuzz
