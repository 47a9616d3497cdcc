// The FOLD, SVG and OBJ writers on fuzzed folded sheets: they must write without failing.
#include <unistd.h>

#include <filesystem>

#include "engine/fabrication/svg_crease_pattern.hpp"
#include "engine/io/fold_format.hpp"
#include "engine/io/obj_writer.hpp"
#include "fuzz/fuzz_support.hpp"

using namespace curvefold;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  static const std::filesystem::path dir = [] {
    auto path = std::filesystem::temp_directory_path() /
                ("curvefold-fuzz-writers-" + std::to_string(getpid()));
    std::filesystem::create_directories(path);
    return path;
  }();
  FuzzedDataProvider data(bytes, size);
  Sheet sheet;
  if (!fuzz::fuzzedSurface(data, sheet)) return 0;
  FoldSession session(sheet);
  for (int i = data.ConsumeIntegralInRange(0, 3); i > 0; --i) {
    const glm::dvec3 grab = session.beginDragNear({data.ConsumeFloatingPointInRange(-0.2, 0.2),
                                                   data.ConsumeFloatingPointInRange(-0.2, 0.2),
                                                   data.ConsumeFloatingPointInRange(-0.2, 0.2)});
    session.updateDrag(grab + glm::dvec3(data.ConsumeFloatingPointInRange(-0.2, 0.2),
                                         data.ConsumeFloatingPointInRange(-0.2, 0.2),
                                         data.ConsumeFloatingPointInRange(-0.2, 0.2)));
    session.commit();
  }
  writeFold(session.fixed(), dir / "x.fold");
  writeSvgCreasePattern(session.fixed(), dir / "x.svg");
  writeObj(session.fixed(), dir / "x.obj");
  return 0;
}
