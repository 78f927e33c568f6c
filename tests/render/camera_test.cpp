// The camera contract of docs/camera.md, checked on the CPU reference the shader mirrors.
#include "render/camera.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace zs {
namespace {

double dot(const Vec3& a, const Vec3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

void expectOrthonormal(const CameraBasis& b) {
  EXPECT_NEAR(dot(b.forward, b.forward), 1, 1e-12);
  EXPECT_NEAR(dot(b.right, b.right), 1, 1e-12);
  EXPECT_NEAR(dot(b.up, b.up), 1, 1e-12);
  EXPECT_NEAR(dot(b.forward, b.right), 0, 1e-12);
  EXPECT_NEAR(dot(b.forward, b.up), 0, 1e-12);
  EXPECT_NEAR(dot(b.right, b.up), 0, 1e-12);
}

TEST(Camera, DefaultBasisLooksDownMinusZ) {
  Camera c;  // eye (0,0,4), target origin, up +y
  const CameraBasis b = cameraBasis(c);
  expectOrthonormal(b);
  EXPECT_NEAR(b.forward[2], -1, 1e-12);
  EXPECT_NEAR(b.right[0], 1, 1e-12);  // forward x up = (0,0,-1) x (0,1,0) = (1,0,0)
  EXPECT_NEAR(b.up[1], 1, 1e-12);
}

TEST(Camera, PerspectivePixelRaysFollowTheFormula) {
  Camera c;
  c.eye = {1, 2, 5};
  c.target = {0, 0.5, 0};
  c.fovY = 50;
  const int w = 40, h = 30;
  const CameraBasis b = cameraBasis(c);
  const double tanHalf = std::tan(25.0 * M_PI / 180.0);
  for (int j : {0, 7, 29})
    for (int i : {0, 13, 39}) {
      const double u = (2 * (i + 0.5) / w - 1) * tanHalf * w / h;
      const double v = (1 - 2 * (j + 0.5) / h) * tanHalf;
      Vec3 d{};
      for (int k = 0; k < 3; ++k) d[k] = b.forward[k] + u * b.right[k] + v * b.up[k];
      const double len = std::sqrt(dot(d, d));
      const Ray ray = primaryRay(c, w, h, i, j);
      for (int k = 0; k < 3; ++k) {
        EXPECT_DOUBLE_EQ(ray.origin[k], c.eye[k]);
        EXPECT_NEAR(ray.direction[k], d[k] / len, 1e-12);
      }
    }
  // Top-left pixel looks up and left: v > 0 along up', u < 0 along right.
  const Ray corner = primaryRay(c, w, h, 0, 0);
  EXPECT_GT(dot(corner.direction, b.up), 0);
  EXPECT_LT(dot(corner.direction, b.right), 0);
}

TEST(Camera, OrthographicOffsetsOriginsNotDirections) {
  Camera c;
  c.projection = Projection::Orthographic;
  c.height = 4;
  const Ray r = primaryRay(c, 100, 50, 99, 0);  // top-right pixel
  EXPECT_NEAR(r.direction[2], -1, 1e-12);
  EXPECT_NEAR(r.origin[0], (2 * 99.5 / 100 - 1) * 2 * 2, 1e-12);  // u' = (...)*(h/2)*W/H
  EXPECT_NEAR(r.origin[1], (1 - 2 * 0.5 / 50) * 2, 1e-12);
  EXPECT_NEAR(r.origin[2], 4, 1e-12);
}

TEST(Camera, DegenerateInputStillGivesABasis) {
  Camera parallel;
  parallel.eye = {0, 5, 0};  // looking straight down the up vector
  expectOrthonormal(cameraBasis(parallel));
  Camera same;
  same.eye = same.target = {1, 1, 1};
  const CameraBasis b = cameraBasis(same);
  expectOrthonormal(b);
  EXPECT_NEAR(b.forward[2], -1, 1e-12);
  Camera zeroUp;
  zeroUp.up = {0, 0, 0};
  expectOrthonormal(cameraBasis(zeroUp));
}

// The box proxy is rasterized with this matrix: a point on pixel (i, j)'s ray must land
// on that pixel's center in normalized device coordinates.
TEST(Camera, ViewProjectionPutsRayPointsOnTheirPixelCenters) {
  for (Projection projection : {Projection::Perspective, Projection::Orthographic}) {
    Camera c;
    c.eye = {1.5, -2, 3};
    c.target = {0.2, 0.1, -0.3};
    c.projection = projection;
    const int w = 64, h = 48;
    const auto m = viewProjection(c, w, h, 1e-3, 50);
    for (auto [i, j] : {std::pair{0, 0}, {63, 47}, {20, 30}}) {
      const Ray r = primaryRay(c, w, h, i, j);
      for (double t : {0.5, 2.0, 7.0}) {
        double x[4] = {r.origin[0] + t * r.direction[0], r.origin[1] + t * r.direction[1],
                       r.origin[2] + t * r.direction[2], 1};
        double clip[4] = {};
        for (int row = 0; row < 4; ++row)
          for (int col = 0; col < 4; ++col) clip[row] += m[col * 4 + row] * x[col];
        EXPECT_NEAR(clip[0] / clip[3], 2 * (i + 0.5) / w - 1, 1e-5);
        EXPECT_NEAR(clip[1] / clip[3], 1 - 2 * (j + 0.5) / h, 1e-5);  // NDC y points up
        EXPECT_GT(clip[2] / clip[3], -1);
        EXPECT_LT(clip[2] / clip[3], 1);
      }
    }
  }
}

}  // namespace
}  // namespace zs
