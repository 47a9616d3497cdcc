#include "interaction/xr/xr_check.hpp"

#include <openxr/openxr_reflection.h>

namespace curvefold {

std::string xrResultName(XrResult result) {
  switch (result) {
#define CURVEFOLD_XR_RESULT_CASE(name, value) \
  case name:                                  \
    return #name;
    XR_LIST_ENUM_XrResult(CURVEFOLD_XR_RESULT_CASE)
#undef CURVEFOLD_XR_RESULT_CASE
            default : return "XrResult(" +
                      std::to_string(static_cast<int>(result)) + ")";
  }
}

XrResult xrCheck(XrResult result, const char* call, const char* file, int line) {
  if (XR_SUCCEEDED(result)) return result;
  std::string where = file;
  // The path from the repository root is enough to find the line.
  if (const auto root = where.rfind("interaction/"); root != std::string::npos)
    where.erase(0, root);
  else if (const auto app = where.rfind("app/"); app != std::string::npos)
    where.erase(0, app);
  throw XrError(std::string(call) + " failed with " + xrResultName(result) + " (" + where + ":" +
                    std::to_string(line) + ")",
                result);
}

}  // namespace curvefold
