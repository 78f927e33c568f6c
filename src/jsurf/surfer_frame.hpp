#pragma once
// How SURFER frames a surface, and the same picture in zeroset's terms. SURFER (IMAGINARY's
// jsurf renderer) keeps three coordinate systems: camera space (the eye at the origin,
// looking down -z, +y up), clipping space, where the surface is cut by the unit sphere, and
// surface space, where F is evaluated:
//   clipping = transform_matrix * rotation_matrix * camera_transform^-1 * camera
//   surface  = 10^scale_factor * clipping
// so `scale_factor` is the zoom (the clipping sphere's radius is 10^scale_factor in F's
// units), `rotation_matrix` turns the surface under a fixed camera, and `camera_transform`
// places the camera (SURFER's own files: 1 unit in front of the sphere's centre). The
// lights live in camera space. zeroset's world is surface space; this file converts both
// ways (docs/jsurf.md).
#include <array>

#include "render/settings.hpp"

namespace zs::jsurf {

// Row-major, as SURFER writes them: m[row][column], points are columns.
using Mat4 = std::array<std::array<double, 4>, 4>;

Mat4 identity4();
Mat4 multiply(const Mat4& a, const Mat4& b);
// The inverse of an affine matrix (last row 0 0 0 1); nothing when it is singular.
bool invertAffine(const Mat4& m, Mat4& inverse);
Vec3 transformPoint(const Mat4& m, const Vec3& p);
Vec3 transformVector(const Mat4& m, const Vec3& v);

// SURFER's view of a scene: the keys that decide what is seen from where.
struct SurferView {
  Mat4 rotation = identity4();         // transform_matrix * rotation_matrix
  Mat4 cameraTransform = identity4();  // camera_transform: world -> camera
  double scaleFactor = 0.0;            // log10 of the clipping sphere's radius
  bool orthographic = true;            // camera_type
  double fovY = 60.0;                  // camera_fov_y, degrees
  double height = 2.0;                 // camera_height, in clipping-space units
};

// SURFER's camera_transform when a file has none: the distance at which the clipping
// sphere just fits (JSurferRenderPanel.setOptimalCameraDistance).
Mat4 surferDefaultCameraTransform(bool orthographic, double fovY);

// camera space -> surface space (zeroset's world).
Mat4 cameraToWorld(const SurferView& view);

// The zeroset camera and clipping ball that show what SURFER shows. The target is the point
// of the line of sight nearest the sphere's centre; up is made unit and orthogonal.
struct ZerosetFrame {
  Camera camera;
  Domain domain;
};
ZerosetFrame toZeroset(const SurferView& view);

// The reverse: `camera` looking into the ball of `radius` about the origin.
SurferView toSurfer(const Camera& camera, double radius);

}  // namespace zs::jsurf
