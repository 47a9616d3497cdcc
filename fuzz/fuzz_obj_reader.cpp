// The OBJ reader: any bytes either make a valid sheet or raise ObjError, never anything else.
#include <sstream>

#include "engine/geometry/validate.hpp"
#include "engine/surfaces/obj_surface.hpp"
#include "fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(bytes), size));
  try {
    const curvefold::Sheet sheet = curvefold::parseObjSurface(in, "fuzz.obj");
    curvefold::ValidationOptions options;
    options.relativeLengthTolerance = curvefold::kObjRelativeTolerance;
    curvefold::validate(sheet, options);  // accepted means valid
  } catch (const curvefold::ObjError&) {
  }
  return 0;
}
