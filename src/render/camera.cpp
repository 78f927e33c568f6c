#include "render/camera.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace zs {
namespace {

Vec3 sub(const Vec3& a, const Vec3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double length(const Vec3& a) {
  return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}
Vec3 scaled(const Vec3& a, double s) {
  return {a[0] * s, a[1] * s, a[2] * s};
}
Vec3 axpy(const Vec3& a, double s, const Vec3& b) {  // a + s*b
  return {a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]};
}

}  // namespace

CameraBasis cameraBasis(const Camera& camera) {
  CameraBasis b;
  b.eye = camera.eye;
  Vec3 f = sub(camera.target, camera.eye);
  double fl = length(f);
  b.forward = (fl > 0 && std::isfinite(fl)) ? scaled(f, 1 / fl) : Vec3{0, 0, -1};
  Vec3 r = cross(b.forward, camera.up);
  double rl = length(r);
  if (!(rl > 1e-12 * std::max(1.0, length(camera.up)))) {
    // up is parallel to forward (or zero): use the world axis least aligned with forward.
    int axis = 0;
    for (int k = 1; k < 3; ++k)
      if (std::abs(b.forward[k]) < std::abs(b.forward[axis])) axis = k;
    Vec3 up{0, 0, 0};
    up[axis] = 1;
    r = cross(b.forward, up);
    rl = length(r);
  }
  b.right = scaled(r, 1 / rl);
  b.up = cross(b.right, b.forward);
  return b;
}

double imagePlaneHalfHeight(const Camera& camera) {
  if (camera.projection == Projection::Orthographic) return std::max(camera.height, 1e-9) / 2;
  double fov = std::clamp(camera.fovY, 1e-6, 180.0 - 1e-6);
  return std::tan(fov * std::numbers::pi / 360.0);
}

Ray primaryRay(const Camera& camera, int width, int height, double i, double j) {
  const CameraBasis b = cameraBasis(camera);
  const double s = imagePlaneHalfHeight(camera);
  const double aspect = double(width) / double(height);
  const double u = (2 * (i + 0.5) / width - 1) * s * aspect;
  const double v = (1 - 2 * (j + 0.5) / height) * s;
  Ray ray;
  if (camera.projection == Projection::Orthographic) {
    ray.origin = axpy(axpy(b.eye, u, b.right), v, b.up);
    ray.direction = b.forward;
  } else {
    ray.origin = b.eye;
    Vec3 d = axpy(axpy(b.forward, u, b.right), v, b.up);
    ray.direction = scaled(d, 1 / length(d));
  }
  return ray;
}

std::array<float, 16> viewProjection(const Camera& camera, int width, int height, double nearDist,
                                     double farDist) {
  const CameraBasis b = cameraBasis(camera);
  const double s = imagePlaneHalfHeight(camera), aspect = double(width) / double(height);
  const bool ortho = camera.projection == Projection::Orthographic;
  auto dot = [](const Vec3& a, const Vec3& c) { return a[0] * c[0] + a[1] * c[1] + a[2] * c[2]; };
  // Rows: x_ndc = dot(X - eye, right) / (s * aspect * w), y_ndc likewise with up' and s,
  // w = depth along forward (perspective) or 1 (orthographic).
  const double zA = ortho ? 2 / farDist : (farDist + nearDist) / (farDist - nearDist);
  const double zB = ortho ? -1 : -2 * farDist * nearDist / (farDist - nearDist);
  const std::array<std::array<double, 4>, 4> rows = {{
      {b.right[0] / (s * aspect), b.right[1] / (s * aspect), b.right[2] / (s * aspect),
       -dot(b.right, b.eye) / (s * aspect)},
      {b.up[0] / s, b.up[1] / s, b.up[2] / s, -dot(b.up, b.eye) / s},
      {zA * b.forward[0], zA * b.forward[1], zA * b.forward[2], -zA * dot(b.forward, b.eye) + zB},
      ortho
          ? std::array<double, 4>{0, 0, 0, 1}
          : std::array<double, 4>{b.forward[0], b.forward[1], b.forward[2], -dot(b.forward, b.eye)},
  }};
  std::array<float, 16> m{};
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m[c * 4 + r] = float(rows[r][c]);
  return m;
}

Vec3 cameraVectorToWorld(const Camera& camera, const Vec3& v) {
  const CameraBasis b = cameraBasis(camera);
  Vec3 out{};
  for (int k = 0; k < 3; ++k) out[k] = v[0] * b.right[k] + v[1] * b.up[k] - v[2] * b.forward[k];
  return out;
}

Vec3 cameraPointToWorld(const Camera& camera, const Vec3& p) {
  const CameraBasis b = cameraBasis(camera);
  const Vec3 v = cameraVectorToWorld(camera, p);
  return {b.eye[0] + v[0], b.eye[1] + v[1], b.eye[2] + v[2]};
}

Vec3 worldVectorToCamera(const Camera& camera, const Vec3& v) {
  const CameraBasis b = cameraBasis(camera);
  auto dot = [&](const Vec3& a) { return v[0] * a[0] + v[1] * a[1] + v[2] * a[2]; };
  return {dot(b.right), dot(b.up), -dot(b.forward)};
}

Vec3 worldPointToCamera(const Camera& camera, const Vec3& p) {
  const CameraBasis b = cameraBasis(camera);
  return worldVectorToCamera(camera, {p[0] - b.eye[0], p[1] - b.eye[1], p[2] - b.eye[2]});
}

}  // namespace zs
