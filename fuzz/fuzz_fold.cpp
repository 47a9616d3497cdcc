// The fold operation on fuzzed sheets with fuzzed grabs, targets and history moves; every
// invariant after every step.
#include "fuzz/fuzz_support.hpp"

#include <glm/geometric.hpp>

using namespace curvefold;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  FuzzedDataProvider data(bytes, size);
  Sheet initial;
  if (!fuzz::fuzzedSurface(data, initial)) return 0;
  FoldSession session(initial);
  const SheetReport before = measure(initial);
  const double scale = before.size;
  while (data.remaining_bytes() > 0) {
    switch (data.ConsumeIntegralInRange(0, 4)) {
      case 0:
        session.undo();
        break;
      case 1:
        session.redo();
        break;
      default: {
        const Sheet& fixed = session.fixed();
        const TriangleIndex t = data.ConsumeIntegralInRange<std::uint32_t>(
            0, static_cast<std::uint32_t>(fixed.triangleCount() - 1));
        double a = data.ConsumeProbability<double>(), b = data.ConsumeProbability<double>();
        if (a + b > 1.0) a = 1.0 - a, b = 1.0 - b;
        session.beginDrag({t, {1.0 - a - b, a, b}});
        const int updates = data.ConsumeIntegralInRange(1, 3);
        for (int i = 0; i < updates; ++i) {
          // Targets around the sheet, sometimes within a hair of the grabbed point.
          glm::dvec3 target = session.grabbedPoint();
          if (!data.ConsumeBool()) {
            for (int k = 0; k < 3; ++k)
              target[k] += scale * data.ConsumeFloatingPointInRange(-1.0, 1.0);
          } else {
            target.x += scale * 1e-12 * data.ConsumeIntegralInRange(-3, 3);
          }
          session.updateDrag(target);
          fuzz::checkInvariants(session.current(), before);
        }
        if (data.ConsumeBool())
          session.commit();
        else
          session.cancel();
      }
    }
    fuzz::checkInvariants(session.current(), before);
  }
  return 0;
}
