#include "engine/geometry/principal_moments.hpp"

#include <glm/geometric.hpp>

namespace curvefold {

namespace {

// Adds (w d[r]) d[c] to each entry, the order Eigen's `S += w * d * d.transpose()` takes (the
// callers' results before this function were those).
template <typename Vec, typename Mat>
void addOuter(Mat& scatter, double w, const Vec& d) {
  const Vec wd = w * d;
  for (int c = 0; c < Vec::length(); ++c)
    for (int r = 0; r < Vec::length(); ++r) scatter[c][r] += wd[r] * d[c];
}

}  // namespace

PointMoments pointMoments(const std::vector<glm::dvec3>& points, const std::vector<double>& weights,
                          const std::optional<glm::dvec3>& about) {
  PointMoments m;
  auto weightOf = [&](std::size_t i) { return weights.empty() ? 1.0 : weights[i]; };
  for (std::size_t i = 0; i < points.size(); ++i) {
    m.centre += weightOf(i) * points[i];
    m.weight += weightOf(i);
  }
  if (about)
    m.centre = *about;
  else if (m.weight > 0.0)
    m.centre /= m.weight;
  for (std::size_t i = 0; i < points.size(); ++i)
    addOuter(m.scatter, weightOf(i), points[i] - m.centre);
  return m;
}

PointMoments2 pointMoments(const std::vector<glm::dvec2>& points) {
  PointMoments2 m;
  for (const glm::dvec2& p : points) m.centre += p;
  m.weight = static_cast<double>(points.size());
  if (m.weight > 0.0) m.centre /= m.weight;
  for (const glm::dvec2& p : points) addOuter(m.scatter, 1.0, p - m.centre);
  return m;
}

AreaMoments areaMoments(const Sheet& sheet) {
  AreaMoments m;
  glm::dvec3 first(0.0);
  glm::dmat3 second(0.0);
  for (const Triangle& t : sheet.triangles) {
    const glm::dvec3 a = sheet.positions[t[0]], b = sheet.positions[t[1]];
    const glm::dvec3 c = sheet.positions[t[2]];
    const double w = 0.5 * glm::length(glm::cross(b - a, c - a));
    if (!(w > 0.0)) continue;
    m.area += w;
    const glm::dvec3 s = a + b + c;
    first += (w / 3.0) * s;
    for (const glm::dvec3& v : {a, b, c, s}) addOuter(second, w / 12.0, v);
  }
  if (!(m.area > 0.0)) return m;
  m.centre = first / m.area;
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r)
      m.covariance[c][r] = second[c][r] / m.area - m.centre[r] * m.centre[c];
  return m;
}

}  // namespace curvefold
