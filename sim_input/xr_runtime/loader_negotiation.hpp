// The loader <-> runtime negotiation ABI of the Khronos OpenXR loader (its loader_interfaces.h,
// interface version 1), which Debian's libopenxr-dev does not install. Field for field as the
// loader declares them: the loader calls xrNegotiateLoaderRuntimeInterface with these.
#pragma once

#include <cstddef>
#include <cstdint>

#include <openxr/openxr.h>

namespace curvefold::simxr {

enum XrLoaderInterfaceStructs {
  XR_LOADER_INTERFACE_STRUCT_UNINTIALIZED = 0,
  XR_LOADER_INTERFACE_STRUCT_LOADER_INFO,
  XR_LOADER_INTERFACE_STRUCT_API_LAYER_REQUEST,
  XR_LOADER_INTERFACE_STRUCT_RUNTIME_REQUEST,
  XR_LOADER_INTERFACE_STRUCT_API_LAYER_CREATE_INFO,
  XR_LOADER_INTERFACE_STRUCT_API_LAYER_NEXT_INFO,
};

inline constexpr std::uint32_t kLoaderInfoStructVersion = 1;
inline constexpr std::uint32_t kRuntimeInfoStructVersion = 1;
inline constexpr std::uint32_t kLoaderRuntimeInterfaceVersion = 1;

struct XrNegotiateLoaderInfo {
  XrLoaderInterfaceStructs structType;  // LOADER_INFO
  std::uint32_t structVersion;
  std::size_t structSize;
  std::uint32_t minInterfaceVersion;
  std::uint32_t maxInterfaceVersion;
  XrVersion minApiVersion;
  XrVersion maxApiVersion;
};

struct XrNegotiateRuntimeRequest {
  XrLoaderInterfaceStructs structType;  // RUNTIME_REQUEST
  std::uint32_t structVersion;
  std::size_t structSize;
  std::uint32_t runtimeInterfaceVersion;          // filled in by the runtime
  XrVersion runtimeApiVersion;                    // filled in by the runtime
  PFN_xrGetInstanceProcAddr getInstanceProcAddr;  // filled in by the runtime
};

}  // namespace curvefold::simxr
