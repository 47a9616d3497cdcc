// OpenXR error handling in the style of hello_xr: CHECK_XR(call) throws XrError with the call's
// text, the result's name and file:line, so a failure deep in the XR path reads as one line.
#pragma once

#include <stdexcept>
#include <string>

#include <openxr/openxr.h>

namespace curvefold {

class XrError : public std::runtime_error {
 public:
  XrError(const std::string& message, XrResult result)
      : std::runtime_error(message), result_(result) {}
  XrResult result() const { return result_; }

 private:
  XrResult result_;
};

// What a program was asked for that the runtime or headset lacks: a headless session
// (XR_MND_headless) or tracked hands. The program reports which; the front end says which of its
// options asked for it.
enum class XrFeature { Headless, HandTracking };
class XrMissingFeature : public XrError {
 public:
  XrMissingFeature(const std::string& message, XrResult result, XrFeature feature)
      : XrError(message, result), feature_(feature) {}
  XrFeature feature() const { return feature_; }

 private:
  XrFeature feature_;
};

// "XR_ERROR_SESSION_LOST", or the number for a result this header version does not know. Needs
// no instance (xrResultToString does), so it works before and after one exists.
std::string xrResultName(XrResult result);

// Throws XrError for a failed result; returns success codes (XR_SESSION_LOSS_PENDING, ...).
XrResult xrCheck(XrResult result, const char* call, const char* file, int line);

// An instance's function (an extension's), through xrGetInstanceProcAddr; throws XrError when
// the runtime has none.
template <typename Function>
Function xrFunction(XrInstance instance, const char* name) {
  PFN_xrVoidFunction function = nullptr;
  xrCheck(xrGetInstanceProcAddr(instance, name, &function), name, __FILE__, __LINE__);
  return reinterpret_cast<Function>(function);
}

}  // namespace curvefold

#define CHECK_XR(call) ::curvefold::xrCheck((call), #call, __FILE__, __LINE__)
