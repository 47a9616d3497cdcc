// Whether the tests run under AddressSanitizer. It reserves terabytes of address space and keeps
// freed memory in quarantine, so memory limits and peak-growth checks hold only in the plain build.
#pragma once

namespace curvefold::testing {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif
#else
inline constexpr bool kSanitized = false;
#endif

}  // namespace curvefold::testing
