// The frame's parameters reach the fragment stage as flat varyings (llvmpipe) or as uniforms
// (every GPU driver): both ways draw the same picture for every method and every program
// variant, so the choice (render/program_variant.hpp, FrameStorage) changes only the speed.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include "render_support.hpp"

namespace zs {
namespace {

TEST(FrameStorageChoice, SoftwareRasterizersTakeVaryingsAndGpusUniforms) {
  if (std::getenv("ZS_FRAME_STORAGE")) GTEST_SKIP() << "ZS_FRAME_STORAGE overrides the choice";
  EXPECT_EQ(frameStorageFor("llvmpipe (LLVM 15.0.6, 256 bits)"), FrameStorage::FlatVaryings);
  EXPECT_EQ(frameStorageFor("softpipe"), FrameStorage::FlatVaryings);
  EXPECT_EQ(frameStorageFor("NVIDIA H200/PCIe/SSE2"), FrameStorage::Uniforms);
  EXPECT_EQ(frameStorageFor("AMD Radeon RX 6600 (radeonsi, navi23, LLVM 15.0.6)"),
            FrameStorage::Uniforms);
  EXPECT_EQ(frameStorageFor("Mesa Intel(R) UHD Graphics 620 (KBL GT2)"), FrameStorage::Uniforms);
  EXPECT_EQ(frameStorageFor(""), FrameStorage::Uniforms);
}

TEST(FrameStorageChoice, TheDefineGoesAfterTheVersionLine) {
  const std::string source = "#version 330 core\nvoid main() {}\n";
  EXPECT_EQ(withFrameStorage(source, FrameStorage::FlatVaryings), source);
  EXPECT_EQ(withFrameStorage(source, FrameStorage::Uniforms),
            "#version 330 core\n#define RT_FRAME_UNIFORMS\n#line 2 0\nvoid main() {}\n");
}

struct StorageCase {
  const char* name;
  const char* formula;
  TracingMethod method;
};

class FrameStorageTest : public ::testing::TestWithParam<StorageCase> {};

TEST_P(FrameStorageTest, BothWaysDrawTheSamePictureInEveryVariant) {
  std::string error;
  ASSERT_NE(test::context(Backend::Egl, error), nullptr) << error;
  const StorageCase& c = GetParam();
  test::SurfaceSpec spec{c.formula, {}, 1};
  spec.method = c.method;
  spec.frameStorage = FrameStorage::FlatVaryings;
  auto varyings = test::makeTracer(spec, error);
  if (!varyings && RayTracer().frameStorage() == FrameStorage::Uniforms) {
    // The block needs more varying components than GL promises; NVIDIA's linker says so.
    GTEST_SKIP() << "this driver cannot pass the frame's parameters as varyings (it uses "
                    "uniforms): "
                 << error.substr(0, error.find("--- fragment"));
  }
  ASSERT_NE(varyings, nullptr) << error;
  spec.frameStorage = FrameStorage::Uniforms;
  auto uniforms = test::makeTracer(spec, error);
  ASSERT_NE(uniforms, nullptr) << error;
  EXPECT_EQ(varyings->frameStorage(), FrameStorage::FlatVaryings);
  EXPECT_EQ(uniforms->frameStorage(), FrameStorage::Uniforms);

  // Variants that leave members of the frame block unread (reflection off: primaryWeight),
  // read every one, or add passes and kept hits.
  const std::vector<std::pair<const char*, std::function<void(RenderSettings&)>>> variants = {
      {"defaults", [](RenderSettings&) {}},
      {"no reflection, outline and border",
       [](RenderSettings& s) {
         s.reflection.enabled = false;
         s.silhouette.enabled = true;
         s.border.enabled = true;
       }},
      {"opacity and shadows",
       [](RenderSettings& s) {
         s.opacity = 0.5;
         s.shading.shadows = true;
       }},
  };
  constexpr int kSize = 48;
  for (const auto& [name, change] : variants) {
    SCOPED_TRACE(name);
    RenderSettings s = test::testSettings({1.2, 1.6, 3.0});
    change(s);
    const Frame a = varyings->render(s, Domain{}, kSize, kSize);
    const Frame b = uniforms->render(s, Domain{}, kSize, kSize);
    ASSERT_EQ(a.error, "");
    ASSERT_EQ(b.error, "");
    const ImageDiff diff = compareImages(a.color, b.color, 1);
    EXPECT_LE(diff.maxDifference, 1);
    int hits = 0;
    for (int y = 0; y < kSize; ++y) {
      for (int x = 0; x < kSize; ++x) {
        const float da = a.depth.at(x, y), db = b.depth.at(x, y);
        EXPECT_EQ(std::isinf(da), std::isinf(db)) << x << "," << y;
        if (!std::isinf(da) && !std::isinf(db)) {
          ++hits;
          EXPECT_NEAR(da, db, 1e-5 * std::abs(da)) << x << "," << y;
        }
      }
    }
    EXPECT_GT(hits, kSize * kSize / 8);  // the surface is in the picture
  }
}

INSTANTIATE_TEST_SUITE_P(
    Methods, FrameStorageTest,
    ::testing::Values(
        StorageCase{"bernstein", "x^4+y^4+z^4-1", TracingMethod::Bernstein},
        StorageCase{"interval", "x^2+y^2+z^2-1+0.1*sin(5*x)", TracingMethod::Interval},
        StorageCase{"sampling", "x^2*y^2+y^2*z^2+z^2*x^2-0.1", TracingMethod::Sampling}),
    [](const ::testing::TestParamInfo<StorageCase>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace zs
