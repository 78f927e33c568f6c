// Arcball with glm quaternions. The drag's rotation is found in camera coordinates (x right,
// y up, z towards the viewer) and carried to world space through the camera basis.
#include "interact/arcball.hpp"

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "render/camera.hpp"

namespace zs::interact {
namespace {

glm::dvec3 toGlm(const Vec3& v) {
  return {v[0], v[1], v[2]};
}
Vec3 fromGlm(const glm::dvec3& v) {
  return {v.x, v.y, v.z};
}

// Cursor -> point on the unit sphere (inside) or on the hyperbolic sheet (outside), so
// dragging past the sphere's rim keeps turning smoothly instead of snapping.
glm::dvec3 spherePoint(double x, double y, int width, int height) {
  const double r = 0.5 * std::min(width, height);
  const double px = (x - 0.5 * width) / r, py = (0.5 * height - y) / r;
  const double d2 = px * px + py * py;
  const double pz = d2 <= 0.5 ? std::sqrt(1.0 - d2) : 0.5 / std::sqrt(d2);
  return glm::normalize(glm::dvec3(px, py, pz));
}

// The world-space rotation that takes the press point to the current point, or identity.
bool dragRotation(const Camera& view, const DragPoints& drag, glm::dquat& out) {
  if (drag.width <= 0 || drag.height <= 0) return false;
  const glm::dvec3 p0 = spherePoint(drag.x0, drag.y0, drag.width, drag.height);
  const glm::dvec3 p1 = spherePoint(drag.x1, drag.y1, drag.width, drag.height);
  const glm::dvec3 axisCam = glm::cross(p0, p1);
  const double s = glm::length(axisCam);
  if (s < 1e-12) return false;
  const double angle = std::atan2(s, glm::dot(p0, p1));
  const CameraBasis b = cameraBasis(view);
  const glm::dvec3 axis =
      axisCam.x * toGlm(b.right) + axisCam.y * toGlm(b.up) - axisCam.z * toGlm(b.forward);
  out = glm::angleAxis(angle, glm::normalize(axis));
  return true;
}

}  // namespace

Camera orbitCamera(const Camera& start, const DragPoints& drag) {
  glm::dquat q;
  if (!dragRotation(start, drag, q)) return start;
  const glm::dquat inverse = glm::conjugate(q);  // the camera turns opposite to the surface
  const CameraBasis b = cameraBasis(start);
  const glm::dvec3 target = toGlm(start.target);
  Camera out = start;
  out.eye = fromGlm(target + inverse * (toGlm(start.eye) - target));
  // The basis' up (orthogonal to the view) rather than the stored one, so the saved camera
  // reproduces the on-screen roll exactly.
  out.up = fromGlm(inverse * toGlm(b.up));
  return out;
}

Vec3 orbitPoint(const Camera& view, const Vec3& point, const DragPoints& drag) {
  glm::dquat q;
  if (!dragRotation(view, drag, q)) return point;
  const glm::dvec3 target = toGlm(view.target);
  return fromGlm(target + q * (toGlm(point) - target));
}

Vec3 orbitDirection(const Camera& view, const Vec3& direction, const DragPoints& drag) {
  glm::dquat q;
  if (!dragRotation(view, drag, q)) return direction;
  return fromGlm(q * toGlm(direction));
}

Camera zoomCamera(const Camera& camera, double wheelSteps) {
  const double factor = std::pow(0.85, wheelSteps);
  Camera out = camera;
  const glm::dvec3 target = toGlm(camera.target);
  const glm::dvec3 offset = toGlm(camera.eye) - target;
  const double distance = glm::length(offset);
  if (distance > 0) {
    const double wanted = std::clamp(distance * factor, 1e-3, 1e4);
    out.eye = fromGlm(target + offset * (wanted / distance));
  }
  if (camera.projection == Projection::Orthographic)
    out.height = std::clamp(camera.height * factor, 1e-3, 1e4);
  return out;
}

}  // namespace zs::interact
