#include "engine/simulation/contact_lanes.hpp"

#include <glm/geometric.hpp>

#include "engine/simulation/lane_clones.hpp"

namespace curvefold {
namespace {

// The lanes' coordinates: in[3 j + axis][k] of lane k's j-th vertex, four lanes a store
// (storeLaneQuad).
[[gnu::always_inline]] inline void gather(const glm::dvec3* x,
                                          const std::array<std::uint32_t, 4>* pairs,
                                          std::size_t count, double (&in)[12][kContactLanes]) {
  static_assert(kContactLanes % 4 == 0);
  for (std::size_t k0 = 0; k0 < kContactLanes; k0 += 4) {
    const std::array<std::uint32_t, 4>* lane[4];
    for (std::size_t q = 0; q < 4; ++q) lane[q] = &pairs[k0 + q < count ? k0 + q : count - 1];
    for (int j = 0; j < 4; ++j)
      for (int axis = 0; axis < 3; ++axis)
        storeLaneQuad(&in[3 * j + axis][k0], x[(*lane[0])[j]][axis], x[(*lane[1])[j]][axis],
                      x[(*lane[2])[j]][axis], x[(*lane[3])[j]][axis]);
  }
}

// triangleDistanceLanes on gathered lanes. Without branches (the tests joined by &, not &&, which
// branches; each choice a select) so that the loop vectorizes. The regions are taken as
// nearestTriangleWeights takes them: each later select overrides, so the first region in its
// order wins; the division's operands are chosen by the same overrides (a region that divides
// chosen last wins both, a corner needs none), so each weight is the quotient it computes.
[[gnu::always_inline]] inline void distanceLanes(const double (&in)[12][kContactLanes],
                                                 double (&result)[7][kContactLanes]) {
  for (std::size_t k = 0; k < kContactLanes; ++k) {
    const glm::dvec3 p(in[0][k], in[1][k], in[2][k]), a(in[3][k], in[4][k], in[5][k]);
    const glm::dvec3 b(in[6][k], in[7][k], in[8][k]), c(in[9][k], in[10][k], in[11][k]);
    const glm::dvec3 ab = b - a, ac = c - a, ap = p - a, bp = p - b, cp = p - c;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    const double vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
    const double sum = va + vb + vc;
    const bool degenerate = !(sum > 0.0);  // its first corner
    const bool bc = (va <= 0.0) & ((d4 - d3) >= 0.0) & ((d5 - d6) >= 0.0);
    const bool acEdge = (vb <= 0.0) & (d2 >= 0.0) & (d6 <= 0.0);
    const bool cCorner = (d6 >= 0.0) & (d5 <= d6);
    const bool abEdge = (vc <= 0.0) & (d1 >= 0.0) & (d3 <= 0.0);
    const bool bCorner = (d3 >= 0.0) & (d4 <= d3);
    const bool aCorner = (d1 <= 0.0) & (d2 <= 0.0);
    // The face's v = vb / sum, or an edge's parameter: nearestTriangleWeights' quotients.
    double numerator = vb, denominator = sum;
    numerator = bc ? d4 - d3 : numerator;
    denominator = bc ? (d4 - d3) + (d5 - d6) : denominator;
    numerator = acEdge ? d2 : numerator;
    denominator = acEdge ? d2 - d6 : denominator;
    numerator = abEdge ? d1 : numerator;
    denominator = abEdge ? d1 - d3 : denominator;
    const double q = numerator / denominator, w = vc / sum;
    double w0 = 1.0 - q - w, w1 = q, w2 = w;  // the face
    w0 = degenerate ? 1.0 : w0;
    w1 = degenerate ? 0.0 : w1;
    w2 = degenerate ? 0.0 : w2;
    w0 = bc ? 0.0 : w0;
    w1 = bc ? 1.0 - q : w1;
    w2 = bc ? q : w2;
    w0 = acEdge ? 1.0 - q : w0;
    w1 = acEdge ? 0.0 : w1;
    w2 = acEdge ? q : w2;
    w0 = cCorner ? 0.0 : w0;
    w1 = cCorner ? 0.0 : w1;
    w2 = cCorner ? 1.0 : w2;
    w0 = abEdge ? 1.0 - q : w0;
    w1 = abEdge ? q : w1;
    w2 = abEdge ? 0.0 : w2;
    w0 = bCorner ? 0.0 : w0;
    w1 = bCorner ? 1.0 : w1;
    w2 = bCorner ? 0.0 : w2;
    w0 = aCorner ? 1.0 : w0;
    w1 = aCorner ? 0.0 : w1;
    w2 = aCorner ? 0.0 : w2;
    const glm::dvec3 away = p - (w0 * a + w1 * b + w2 * c);
    result[0][k] = away.x;
    result[1][k] = away.y;
    result[2][k] = away.z;
    result[3][k] = glm::length(away);
    result[4][k] = w0;
    result[5][k] = w1;
    result[6][k] = w2;
  }
}

}  // namespace

CURVEFOLD_LANE_CLONES void triangleDistanceLanes(const glm::dvec3* x,
                                                 const std::array<std::uint32_t, 4>* pairs,
                                                 std::size_t count,
                                                 double (&out)[7][kContactLanes]) {
  alignas(64) double in[12][kContactLanes], result[7][kContactLanes];
  gather(x, pairs, count, in);
  distanceLanes(in, result);
  for (int j = 0; j < 7; ++j)
    for (std::size_t k = 0; k < count; ++k) out[j][k] = result[j][k];
}

}  // namespace curvefold
