#include "jsurf/surfer_frame.hpp"

#include <cmath>

namespace zs::jsurf {
namespace {

double dot(const Vec3& a, const Vec3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
double length(const Vec3& a) {
  return std::sqrt(dot(a, a));
}
Vec3 scaled(const Vec3& a, double s) {
  return {a[0] * s, a[1] * s, a[2] * s};
}
Vec3 add(const Vec3& a, const Vec3& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
Vec3 sub(const Vec3& a, const Vec3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3 normalized(const Vec3& a) {
  const double l = length(a);
  return l > 0 ? scaled(a, 1.0 / l) : a;
}

}  // namespace

Mat4 identity4() {
  Mat4 m{};
  for (int i = 0; i < 4; ++i) m[i][i] = 1.0;
  return m;
}

Mat4 multiply(const Mat4& a, const Mat4& b) {
  Mat4 m{};
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      for (int k = 0; k < 4; ++k) m[r][c] += a[r][k] * b[k][c];
  return m;
}

bool invertAffine(const Mat4& m, Mat4& inverse) {
  // Cofactors of the 3x3 linear part, then the translation moved to the other side.
  const auto& a = m;
  const double c00 = a[1][1] * a[2][2] - a[1][2] * a[2][1];
  const double c01 = a[1][2] * a[2][0] - a[1][0] * a[2][2];
  const double c02 = a[1][0] * a[2][1] - a[1][1] * a[2][0];
  const double det = a[0][0] * c00 + a[0][1] * c01 + a[0][2] * c02;
  if (!std::isfinite(det) || std::abs(det) < 1e-300) return false;
  const double k = 1.0 / det;
  Mat4 r = identity4();
  r[0][0] = c00 * k;
  r[1][0] = c01 * k;
  r[2][0] = c02 * k;
  r[0][1] = (a[0][2] * a[2][1] - a[0][1] * a[2][2]) * k;
  r[1][1] = (a[0][0] * a[2][2] - a[0][2] * a[2][0]) * k;
  r[2][1] = (a[0][1] * a[2][0] - a[0][0] * a[2][1]) * k;
  r[0][2] = (a[0][1] * a[1][2] - a[0][2] * a[1][1]) * k;
  r[1][2] = (a[0][2] * a[1][0] - a[0][0] * a[1][2]) * k;
  r[2][2] = (a[0][0] * a[1][1] - a[0][1] * a[1][0]) * k;
  for (int row = 0; row < 3; ++row)
    r[row][3] = -(r[row][0] * a[0][3] + r[row][1] * a[1][3] + r[row][2] * a[2][3]);
  inverse = r;
  return true;
}

Vec3 transformPoint(const Mat4& m, const Vec3& p) {
  Vec3 out;
  for (int r = 0; r < 3; ++r) out[r] = m[r][0] * p[0] + m[r][1] * p[1] + m[r][2] * p[2] + m[r][3];
  return out;
}

Vec3 transformVector(const Mat4& m, const Vec3& v) {
  Vec3 out;
  for (int r = 0; r < 3; ++r) out[r] = m[r][0] * v[0] + m[r][1] * v[1] + m[r][2] * v[2];
  return out;
}

Mat4 surferDefaultCameraTransform(bool orthographic, double fovY) {
  constexpr double kPi = 3.14159265358979323846;
  const double distance = orthographic ? 1.0 : 1.0 / std::sin(kPi / 180.0 * fovY / 2.0);
  Mat4 m = identity4();
  m[2][3] = -distance;
  return m;
}

Mat4 cameraToWorld(const SurferView& view) {
  Mat4 cameraInverse = identity4();
  invertAffine(view.cameraTransform, cameraInverse);  // a singular one was refused on reading
  Mat4 scale = identity4();
  const double s = std::pow(10.0, view.scaleFactor);
  for (int i = 0; i < 3; ++i) scale[i][i] = s;
  return multiply(scale, multiply(view.rotation, cameraInverse));
}

ZerosetFrame toZeroset(const SurferView& view) {
  const Mat4 m = cameraToWorld(view);
  ZerosetFrame frame;
  Camera& cam = frame.camera;
  cam.eye = transformPoint(m, {0, 0, 0});
  const Vec3 forward = normalized(transformVector(m, {0, 0, -1}));
  const Vec3 upImage = transformVector(m, {0, 1, 0});
  // Along the line of sight, the point nearest the centre; a camera that looks away from
  // the sphere still gets a target in front of it.
  const double radius = std::pow(10.0, view.scaleFactor);
  double t = -dot(cam.eye, forward);
  if (!(t > 1e-9 * radius)) t = radius;
  cam.target = add(cam.eye, scaled(forward, t));
  const Vec3 right = normalized(cross(forward, upImage));
  cam.up = cross(right, forward);
  cam.projection = view.orthographic ? Projection::Orthographic : Projection::Perspective;
  cam.fovY = view.fovY;
  cam.height = view.height * length(upImage);  // camera units -> F's units
  frame.domain.shape = DomainShape::Sphere;
  frame.domain.center = {0, 0, 0};
  frame.domain.radius = radius;
  return frame;
}

SurferView toSurfer(const Camera& camera, double radius) {
  SurferView view;
  const Vec3 forward = normalized(sub(camera.target, camera.eye));
  const Vec3 right = normalized(cross(forward, camera.up));
  const Vec3 up = cross(right, forward);
  // rotation_matrix's columns are the camera's axes in the world: right, up, back.
  for (int r = 0; r < 3; ++r) {
    view.rotation[r][0] = right[r];
    view.rotation[r][1] = up[r];
    view.rotation[r][2] = -forward[r];
  }
  // The eye in the rotated, unscaled frame; camera_transform moves it to the origin.
  const Vec3 eye = scaled(camera.eye, 1.0 / radius);
  Vec3 local{dot(right, eye), dot(up, eye), -dot(forward, eye)};
  // Rounding leaves crumbs of 1e-17 where the eye is on the axis: SURFER's own files say 0.
  for (double& c : local)
    if (std::abs(c) < 1e-12 * length(eye)) c = 0;
  view.cameraTransform = identity4();
  for (int r = 0; r < 3; ++r) view.cameraTransform[r][3] = -local[r];
  view.scaleFactor = std::log10(radius);
  view.orthographic = camera.projection == Projection::Orthographic;
  view.fovY = camera.fovY;
  view.height = camera.height / radius;
  return view;
}

}  // namespace zs::jsurf
