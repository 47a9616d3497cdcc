// CURVEFOLD_LANE_CLONES: the attribute that gives a lane loop (a kernel written on local arrays,
// one element a lane, so the compiler vectorizes it) an AVX2 copy beside the default one, chosen
// by the loader (an ifunc). Used by the dynamic step's bar and hinge lanes (dynamic_solver.cpp)
// and the contact list's distance lanes (contact_lanes.cpp); their sources are compiled without
// errno on math calls, without floating-point traps and without contraction (CMakeLists.txt), so
// each copy gives the scalar code's bits. ThreadSanitizer's runtime is not up when the loader runs
// ifunc resolvers (every test binary crashed at start), so under it only the default copy is built.
#pragma once

#if defined(__SANITIZE_THREAD__)
#define CURVEFOLD_LANE_CLONES
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define CURVEFOLD_LANE_CLONES
#endif
#endif
#ifndef CURVEFOLD_LANE_CLONES
#define CURVEFOLD_LANE_CLONES [[gnu::target_clones("avx2", "default")]]
#endif

namespace curvefold {

// Four lanes of a lane kernel's input written with one 32-byte store, dst 32-byte aligned. A
// gather that fills a lane array one double at a time leaves the kernel's 4-wide loads to wait
// for those stores to retire (a load spanning several smaller stores is not forwarded from them);
// the quadruple built in registers is. The values are copied, not computed: the same bits.
using LaneQuad = double __attribute__((vector_size(32)));
[[gnu::always_inline]] inline void storeLaneQuad(double* dst, double a, double b, double c,
                                                 double d) {
  const LaneQuad quad = {a, b, c, d};
  __builtin_memcpy(dst, &quad, sizeof quad);
}

}  // namespace curvefold
