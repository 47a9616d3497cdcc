#include "app/desktop/desktop_input.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "engine/render/scene_builder.hpp"

namespace curvefold::desktop {

namespace {

glm::mat4 matrixOf(const Pose& pose) {
  glm::mat4 m = glm::mat4_cast(glm::quat(pose.orientation));
  m[3] = glm::vec4(glm::vec3(pose.position), 1.0f);
  return m;
}

}  // namespace

std::optional<glm::dvec3> intersectSheet(const Ray& ray, const Sheet& sheet,
                                         const Pose& worldFromSheet) {
  // In sheet coordinates, so the sheet's own doubles are used as they are.
  const Pose sheetFromWorld = worldFromSheet.inverse();
  const glm::dvec3 origin = sheetFromWorld.apply(ray.origin);
  const glm::dvec3 direction = sheetFromWorld.applyToDirection(ray.direction);
  double best = std::numeric_limits<double>::infinity();
  for (const auto& triangle : sheet.triangles) {
    // Moller-Trumbore, two-sided.
    const glm::dvec3 a = sheet.positions[triangle[0]];
    const glm::dvec3 e1 = sheet.positions[triangle[1]] - a;
    const glm::dvec3 e2 = sheet.positions[triangle[2]] - a;
    const glm::dvec3 p = glm::cross(direction, e2);
    const double det = glm::dot(e1, p);
    if (std::abs(det) < 1e-300) continue;
    const double inverse = 1.0 / det;
    const glm::dvec3 s = origin - a;
    const double u = glm::dot(s, p) * inverse;
    if (u < 0.0 || u > 1.0) continue;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(direction, q) * inverse;
    if (v < 0.0 || u + v > 1.0) continue;
    const double t = glm::dot(e2, q) * inverse;
    if (t > 0.0 && t < best) best = t;
  }
  if (!std::isfinite(best)) return std::nullopt;
  return worldFromSheet.apply(origin + best * direction);
}

OrbitCamera OrbitCamera::framing(const Sheet& sheet, const Pose& worldFromSheet, float aspect) {
  return framing(worldBounds(sheet, matrixOf(worldFromSheet)), aspect);
}

Bounds studioBounds(const Sheet& sheet, const TriangleMesh* target, const Pose& worldFromSheet) {
  Bounds bounds = worldBounds(sheet, matrixOf(worldFromSheet));
  if (target)
    for (const glm::dvec3& p : target->positions) bounds.add(glm::vec3(worldFromSheet.apply(p)));
  return bounds;
}

bool OrbitCamera::shows(const Bounds& bounds, double width, double height) const {
  if (bounds.empty()) return true;
  const glm::dvec3 f = forward();
  for (int corner = 0; corner < 8; ++corner) {
    const glm::dvec3 p((corner & 1) ? bounds.max.x : bounds.min.x,
                       (corner & 2) ? bounds.max.y : bounds.min.y,
                       (corner & 4) ? bounds.max.z : bounds.min.z);
    if (glm::dot(p - eye(), f) <= 0.0) return false;
    const glm::dvec2 at = project(p, width, height);
    if (at.x < 0.0 || at.x > width || at.y < 0.0 || at.y > height) return false;
  }
  return true;
}

bool followSheet(OrbitCamera& camera, bool sheetWasShown, const Bounds& sheet, const Bounds& framed,
                 double width, double height) {
  if (!sheetWasShown || camera.shows(sheet, width, height)) return false;
  camera = OrbitCamera::framing(framed, float(width / height));
  return true;
}

OrbitCamera OrbitCamera::framing(const Bounds& bounds, float aspect) {
  const Camera framed = frameBounds(bounds, ViewPreset::Front, aspect);
  OrbitCamera camera;
  camera.target = glm::dvec3(framed.target);
  camera.distance = glm::length(glm::dvec3(framed.eye) - glm::dvec3(framed.target));
  camera.fovYDegrees = framed.fovYDegrees;
  return camera;
}

glm::dvec3 OrbitCamera::forward() const {
  return -glm::dvec3(std::cos(pitch) * std::sin(yaw), std::sin(pitch),
                     std::cos(pitch) * std::cos(yaw));
}

glm::dvec3 OrbitCamera::eye() const {
  return target - distance * forward();
}

Camera OrbitCamera::camera() const {
  Camera camera;
  camera.eye = glm::vec3(eye());
  camera.target = glm::vec3(target);
  camera.up = {0.0f, 1.0f, 0.0f};
  camera.fovYDegrees = static_cast<float>(fovYDegrees);
  // Near and far around the target, so depth precision follows the zoom.
  camera.nearPlane = static_cast<float>(std::max(1e-4, distance * 0.01));
  camera.farPlane = static_cast<float>(distance * 100.0);
  return camera;
}

Ray OrbitCamera::ray(glm::dvec2 pixel, double width, double height) const {
  const glm::dvec3 f = forward();
  const glm::dvec3 right = glm::normalize(glm::cross(f, glm::dvec3(0, 1, 0)));
  const glm::dvec3 up = glm::cross(right, f);
  const double tanHalf = std::tan(glm::radians(fovYDegrees) * 0.5);
  const double x = (2.0 * pixel.x / width - 1.0) * tanHalf * (width / height);
  const double y = (1.0 - 2.0 * pixel.y / height) * tanHalf;
  return {eye(), glm::normalize(f + x * right + y * up)};
}

glm::dvec2 OrbitCamera::project(const glm::dvec3& p, double width, double height) const {
  const glm::dvec3 f = forward();
  const glm::dvec3 right = glm::normalize(glm::cross(f, glm::dvec3(0, 1, 0)));
  const glm::dvec3 up = glm::cross(right, f);
  const glm::dvec3 d = p - eye();
  const double depth = glm::dot(d, f);
  const double tanHalf = std::tan(glm::radians(fovYDegrees) * 0.5);
  const double x = glm::dot(d, right) / depth / (tanHalf * (width / height));
  const double y = glm::dot(d, up) / depth / tanHalf;
  return {(x + 1.0) * 0.5 * width, (1.0 - y) * 0.5 * height};
}

void OrbitCamera::orbit(double dxPixels, double dyPixels) {
  yaw -= dxPixels * 0.008;
  // Short of the poles, where the up vector would flip.
  pitch = std::clamp(pitch + dyPixels * 0.008, -1.5, 1.5);
}

void OrbitCamera::pan(double dxPixels, double dyPixels, double height) {
  const glm::dvec3 f = forward();
  const glm::dvec3 right = glm::normalize(glm::cross(f, glm::dvec3(0, 1, 0)));
  const glm::dvec3 up = glm::cross(right, f);
  const double metresPerPixel =
      2.0 * distance * std::tan(glm::radians(fovYDegrees) * 0.5) / std::max(height, 1.0);
  target += (-dxPixels * right + dyPixels * up) * metresPerPixel;
}

void OrbitCamera::zoom(double wheelSteps) {
  distance = std::clamp(distance * std::pow(0.9, wheelSteps), 1e-3, 1e3);
}

void DesktopInput::mouseRay(const Ray& ray, const Sheet& sheet, const Pose& worldFromSheet) {
  if (dragging_) {
    // The plane through the tip parallel to the screen (its normal fixed at the press).
    const double denominator = glm::dot(ray.direction, planeNormal_);
    if (std::abs(denominator) < 1e-9) return;
    const double t = glm::dot(tip_ - ray.origin, planeNormal_) / denominator;
    if (t > 0.0) tip_ = ray.origin + t * ray.direction;
    return;
  }
  const std::optional<glm::dvec3> hit = intersectSheet(ray, sheet, worldFromSheet);
  tracked_ = hit.has_value();
  if (hit) tip_ = *hit;
}

bool DesktopInput::press(const Ray& ray, const Sheet& sheet, const Pose& worldFromSheet,
                         const glm::dvec3& viewForward) {
  const std::optional<glm::dvec3> hit = intersectSheet(ray, sheet, worldFromSheet);
  if (!hit) return false;
  tip_ = *hit;
  tracked_ = true;
  dragging_ = true;
  planeNormal_ = glm::normalize(viewForward);
  return true;
}

void DesktopInput::release() {
  dragging_ = false;
}

void DesktopInput::wheel(double steps) {
  if (dragging_) tip_ += steps * depthStep_ * planeNormal_;
}

InputFrame DesktopInput::frame(double time) {
  InputFrame frame;
  frame.time = time;
  frame.pointHand.position = tip_;
  frame.pointHand.tracked = tracked_;
  frame.pointHand.select = dragging_ ? 1.0 : 0.0;
  frame.buttons = pulses_;
  pulses_ = 0;
  return frame;
}

}  // namespace curvefold::desktop
