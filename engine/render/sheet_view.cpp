#include "engine/render/sheet_view.hpp"

#include <cmath>

#include <Eigen/Eigenvalues>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "engine/geometry/principal_moments.hpp"
#include "engine/render/scene_builder.hpp"

namespace curvefold {

SheetView viewForSheet(const Sheet& sheet) {
  SheetView view;
  const glm::dvec3 iso(viewDirection(ViewPreset::Iso));
  view.direction = glm::vec3(iso);
  // Area-weighted moments, each triangle's second moment exact.
  const AreaMoments moments = areaMoments(sheet);
  const double area = moments.area;
  if (!(area > 0.0)) return view;
  Eigen::Matrix3d covariance;
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) covariance(r, c) = moments.covariance[c][r];
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  const Eigen::Vector3d variances = solver.eigenvalues();  // ascending
  if (solver.info() != Eigen::Success || !(variances[0] < kFlatVarianceRatio * variances[1]))
    return view;
  const Eigen::Vector3d thin = solver.eigenvectors().col(0);
  glm::dvec3 normal(thin.x(), thin.y(), thin.z());
  // A bowl or a dome opens upwards (its rim higher than its middle: height and squared distance
  // from the centre correlate); any other sheet (a saddle, a plane) faces the iso view's side.
  const glm::dvec3 centreD = moments.centre;
  double hh = 0.0, rr = 0.0, hr = 0.0, rMean = 0.0;
  for (int pass = 0; pass < 2; ++pass)
    for (const Triangle& t : sheet.triangles) {
      const glm::dvec3 a = sheet.positions[t[0]], b = sheet.positions[t[1]];
      const glm::dvec3 c = sheet.positions[t[2]];
      const double w = 0.5 * glm::length(glm::cross(b - a, c - a)) / area;
      if (!(w > 0.0)) continue;
      const glm::dvec3 d = (a + b + c) / 3.0 - centreD;
      const double h = glm::dot(d, normal), r = glm::dot(d, d) - h * h;
      if (pass == 0) {
        rMean += w * r;
        continue;
      }
      hh += w * h * h, rr += w * (r - rMean) * (r - rMean), hr += w * h * (r - rMean);
    }
  const double correlation = hr / std::sqrt(std::max(hh * rr, 1e-300));
  if (std::abs(correlation) > 0.3 ? correlation < 0.0 : glm::dot(normal, iso) < 0.0)
    normal = -normal;
  // The shortest turn of the normal onto +y (about x when it is +z: the sheet's x stays x).
  const glm::dvec3 up(0.0, 1.0, 0.0);
  glm::dvec3 axis = glm::cross(normal, up);
  const double angle = std::atan2(glm::length(axis), glm::dot(normal, up));
  if (glm::length(axis) < 1e-9)
    axis = {1.0, 0.0, 0.0};  // already up, or straight down: a half turn
  const glm::vec3 centre(centreD);
  if (angle > 1e-9)
    view.worldFromSheet =
        glm::translate(glm::mat4(1.0f), centre) *
        glm::rotate(glm::mat4(1.0f), float(angle), glm::vec3(glm::normalize(axis))) *
        glm::translate(glm::mat4(1.0f), -centre);
  // Seen from 35 degrees off the vertical, from the iso view's side.
  const double tilt = glm::radians(35.0);
  const glm::dvec3 side = glm::normalize(glm::dvec3(iso.x, 0.0, iso.z));
  view.direction = glm::vec3(std::cos(tilt) * up + std::sin(tilt) * side);
  return view;
}

}  // namespace curvefold
