#include "engine/fit/tube_reach.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include <glm/geometric.hpp>

#include "engine/fit/nested_rings.hpp"
#include "engine/fit/placed_start.hpp"
#include "engine/fit/ring_folds.hpp"

namespace curvefold {

std::vector<double> upperConcaveHull(const std::vector<glm::dvec2>& profile) {
  // Andrew's monotone chain, the upper half: a point under the chord of its neighbours goes.
  std::vector<glm::dvec2> hull;
  for (const glm::dvec2& p : profile) {
    while (hull.size() >= 2) {
      const glm::dvec2 a = hull[hull.size() - 2], b = hull.back();
      if ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x) < 0.0) break;
      hull.pop_back();
    }
    hull.push_back(p);
  }
  std::vector<double> out;
  out.reserve(profile.size());
  std::size_t k = 0;
  for (const glm::dvec2& p : profile) {
    while (k + 1 < hull.size() && hull[k + 1].x < p.x) ++k;
    if (k + 1 >= hull.size() || !(hull[k + 1].x > hull[k].x)) {
      out.push_back(std::max(p.y, hull[k].y));
      continue;
    }
    const double f = (p.x - hull[k].x) / (hull[k + 1].x - hull[k].x);
    out.push_back(std::max(p.y, hull[k].y + f * (hull[k + 1].y - hull[k].y)));
  }
  return out;
}

std::optional<double> tubeRingsReach(const Sheet& tube, const std::vector<SurfaceSample>& samples,
                                     const RevolutionAxis& axis, TubeHull hullKind) {
  const std::optional<TubeAxis> own = tubeAbout(tube, axis.direction);
  const std::optional<HeightBands> bands = heightBands(samples, axis.point, axis.direction);
  if (!own || !bands) return std::nullopt;
  // The sheet's radius about its own axis as a line of the height along the target's.
  const glm::dvec3 direction = own->axis.direction;
  double n = 0.0, sumH = 0.0, sumR = 0.0, sumHH = 0.0, sumHR = 0.0;
  for (const glm::dvec3& p : tube.positions) {
    const glm::dvec3 d = p - own->axis.point;
    const double h = glm::dot(p - axis.point, axis.direction);
    const double r = glm::length(d - glm::dot(d, direction) * direction);
    n += 1.0;
    sumH += h;
    sumR += r;
    sumHH += h * h;
    sumHR += h * r;
  }
  const double varianceH = sumHH / n - (sumH / n) * (sumH / n);
  const double slope = varianceH > 0.0 ? (sumHR / n - (sumH / n) * (sumR / n)) / varianceH : 0.0;
  const double intercept = sumR / n - slope * sumH / n;
  const std::vector<glm::dvec2>& profile = bands->profile;
  const std::size_t bandCount = profile.size();
  const std::size_t trims = hullKind == TubeHull::EndsMayStandLevel ? bandCount / 4 : 0;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t low = 0; low <= trims; ++low)
    for (std::size_t high = 0; high <= trims; ++high) {  // low + high <= half the bands
      const std::vector<glm::dvec2> kept(profile.begin() + static_cast<std::ptrdiff_t>(low),
                                         profile.end() - static_cast<std::ptrdiff_t>(high));
      const std::vector<double> hull = upperConcaveHull(kept);
      double sum = 0.0, most = 0.0;
      for (std::size_t i = 0; i < bandCount; ++i) {
        const double standing = i < low                 ? hull.front()
                                : i >= bandCount - high ? hull.back()
                                                        : hull[i - low];
        const double envelope = std::min(intercept + slope * profile[i].x, standing);
        const double gap = std::abs(envelope - profile[i].y);
        sum += gap;
        most = std::max(most, gap);
      }
      best = std::min(best, sum / static_cast<double>(bandCount) + kProfileFarthest * most);
    }
  return best;
}

}  // namespace curvefold
