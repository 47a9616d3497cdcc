// The OBJ readers: any bytes either make a valid sheet (or, read as a target, a mesh whose
// indices are in range, which the fit either accepts or refuses by name) or raise ObjError, never
// anything else.
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "engine/fit/crease_planes.hpp"
#include "engine/fit/fold_fit.hpp"
#include "engine/geometry/validate.hpp"
#include "engine/surfaces/obj_surface.hpp"
#include "fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(bytes), size);
  try {
    std::istringstream in(text);
    const curvefold::Sheet sheet = curvefold::parseObjSurface(in, "fuzz.obj");
    curvefold::ValidationOptions options;
    options.relativeLengthTolerance = curvefold::kObjRelativeTolerance;
    curvefold::validate(sheet, options);  // accepted means valid
  } catch (const curvefold::ObjError&) {
  }
  try {
    std::istringstream in(text);
    const curvefold::TriangleMesh mesh = curvefold::parseObjMesh(in, "fuzz.obj");
    for (const auto& t : mesh.triangles)
      for (std::uint32_t v : t)
        if (v >= mesh.positions.size()) std::abort();
    for (const glm::dvec3& p : mesh.positions)
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) std::abort();
    if (mesh.triangles.size() <= 64) {
      curvefold::FitSettings settings;
      settings.denseTargetSamples = 200;
      settings.targetSamples = 50;
      const curvefold::FoldFitter fitter(mesh, settings);
      curvefold::findCreasePlanes(mesh);
    }
  } catch (const curvefold::ObjError&) {
  } catch (const curvefold::InvalidTarget&) {
  }
  return 0;
}
