#pragma once
// The camera contract (docs/camera.md) on the CPU: takes a Camera and an image size, puts
// out the orthonormal basis the shader receives and the exact ray of any pixel. The shader
// repeats primaryRay() in float; tests use this double version as the analytic reference.
#include <array>

#include "render/settings.hpp"

namespace zs {

struct CameraBasis {
  Vec3 eye{};
  Vec3 forward{};  // normalize(target - eye)
  Vec3 right{};    // normalize(forward x up)
  Vec3 up{};       // right x forward
};

// Degenerate input never fails: eye == target looks down -z, and an up vector parallel to
// the view direction is replaced by the world axis least aligned with it (documented).
CameraBasis cameraBasis(const Camera& camera);

// Camera coordinates (lights.space = "camera"): from the eye, x right, y up, z towards the
// viewer, in the world's units. A vector (a direction) and a point into the world, and back.
Vec3 cameraVectorToWorld(const Camera& camera, const Vec3& v);
Vec3 cameraPointToWorld(const Camera& camera, const Vec3& p);
Vec3 worldVectorToCamera(const Camera& camera, const Vec3& v);
Vec3 worldPointToCamera(const Camera& camera, const Vec3& p);

struct Ray {
  Vec3 origin{};
  Vec3 direction{};  // unit length
};

// Ray through pixel (i, j), counted from the top-left; (i + 0.5, j + 0.5) is the pixel
// center, so sub-pixel offsets pass fractional i, j with the 0.5 already removed.
Ray primaryRay(const Camera& camera, int width, int height, double i, double j);

// Scale of the image plane at unit distance: tan(fov_y / 2) for perspective, height / 2
// for orthographic. Clamped so fov_y in (0, 180) and height > 0.
double imagePlaneHalfHeight(const Camera& camera);

// World -> clip matrix (column-major, as glUniformMatrix4fv takes it) that puts any point
// of pixel (i, j)'s ray at that pixel's center: rasterizing geometry with it starts exactly
// the fragments whose rays meet the geometry. Depth maps [nearDist, farDist] along forward
// (perspective) or [0, farDist] (orthographic) to [-1, 1].
std::array<float, 16> viewProjection(const Camera& camera, int width, int height, double nearDist,
                                     double farDist);

}  // namespace zs
