// `zeroset render --animate` without GL: reading KEY=FROM:TO, the value of each frame,
// each frame's scene, when the octree must be rebuilt, the frame file names, the ffmpeg
// command line; and the viewer's play-button sweep.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "app/animate/animation.hpp"
#include "app/animate/render_frames.hpp"
#include "app/animate/video.hpp"
#include "app/viewer/panel.hpp"

namespace zs::app {
namespace {

TEST(Animation, ReadsAParameterSweepAndSpacesFramesEvenlyWithBothEnds) {
  std::string error;
  const auto anim = parseAnimation("params.mu=0.5:1.5", 5, error);
  ASSERT_TRUE(anim) << error;
  EXPECT_EQ(anim->kind, Animation::Kind::Param);
  EXPECT_EQ(anim->param, "mu");
  EXPECT_EQ(anim->key(), "params.mu");
  EXPECT_DOUBLE_EQ(anim->valueAt(0), 0.5);
  EXPECT_DOUBLE_EQ(anim->valueAt(1), 0.75);
  EXPECT_DOUBLE_EQ(anim->valueAt(4), 1.5);
  const auto one = parseAnimation("params.a=-2:3", 1, error);
  ASSERT_TRUE(one) << error;
  EXPECT_DOUBLE_EQ(one->valueAt(0), -2.0) << "one frame shows FROM";
}

TEST(Animation, RefusesMalformedSpecsWithAHowTo) {
  for (const char* bad : {"params.a", "params.a=1", "params.a=x:1", "params.a=0:1e999",
                          "params.=0:1", "=0:1", "clip.=0:1"}) {
    std::string error;
    EXPECT_FALSE(parseAnimation(bad, 10, error)) << bad;
    EXPECT_NE(error.find("error: --animate"), std::string::npos) << bad;
    EXPECT_NE(error.find("hint: write KEY=FROM:TO"), std::string::npos) << bad;
  }
}

TEST(Animation, FrameSceneSetsTheParameterAndRefusesABadName) {
  Scene base;
  base.formula = "x^2 + y^2 + z^2 - r^2";
  std::string error;
  const auto anim = parseAnimation("params.r=1:2", 3, error);
  ASSERT_TRUE(anim);
  Scene frame;
  ASSERT_EQ(frameScene(*anim, base, 1, frame), "");
  ASSERT_EQ(frame.params.size(), 1u);
  EXPECT_EQ(frame.params[0].first, "r");
  EXPECT_DOUBLE_EQ(frame.params[0].second, 1.5);
  EXPECT_EQ(frame.formula, base.formula);

  const auto bad = parseAnimation("params.sin=0:1", 3, error);  // a function's name
  ASSERT_TRUE(bad);
  EXPECT_NE(frameScene(*bad, base, 0, frame), "");
}

TEST(Animation, SurfaceIsRebuiltOnlyWhenTheSchemaSaysSo) {
  Scene base;
  base.formula = "x^2 + y^2 + z^2 - r^2";
  std::string error;
  EXPECT_TRUE(rebuildsEachFrame(*parseAnimation("params.r=1:2", 3, error), base));
  EXPECT_FALSE(rebuildsEachFrame(*parseAnimation("params.unused=1:2", 3, error), base));
  EXPECT_FALSE(rebuildsEachFrame(*parseAnimation("camera.orbit=0:360", 3, error), base));
  // With several surfaces: a parameter of the second one, its level, and what the surfaces'
  // shader holds as constants (the intersection curves, the others' materials lit by the
  // ambient light).
  EXPECT_FALSE(rebuildsEachFrame(*parseAnimation("params.h=0:1", 3, error), base));
  EXPECT_FALSE(rebuildsEachFrame(*parseAnimation("lights.ambient=0:1", 3, error), base));
  base.moreSurfaces = {SurfaceEntry{"z - h", 0, {}}};
  EXPECT_TRUE(rebuildsEachFrame(*parseAnimation("params.h=0:1", 3, error), base));
  EXPECT_TRUE(rebuildsEachFrame(*parseAnimation("surface.2.level=0:1", 3, error), base));
  EXPECT_TRUE(
      rebuildsEachFrame(*parseAnimation("highlights.intersection.tolerance=0:1", 3, error), base));
  EXPECT_TRUE(rebuildsEachFrame(*parseAnimation("lights.ambient=0:1", 3, error), base));
}

TEST(Animation, AnyNumberOfTheSceneGoesThroughSetsChecks) {
  Scene base;
  base.render.clipPlanes = {{true, {0, 0, 1}, 0}};
  std::string error;
  const auto sweep = parseAnimation("clip.plane.1.offset=-1:1", 5, error);
  ASSERT_TRUE(sweep) << error;
  EXPECT_EQ(sweep->key(), "clip.plane.1.offset");
  Scene frame;
  ASSERT_EQ(frameScene(*sweep, base, 3, frame), "");
  EXPECT_DOUBLE_EQ(frame.render.clipPlanes[0].offset, 0.5);
  EXPECT_FALSE(rebuildsEachFrame(*sweep, base));  // a frame parameter
  EXPECT_FALSE(rebuildsEachFrame(*parseAnimation("volume.falloff=0.05:0.5", 5, error), base));
  EXPECT_TRUE(rebuildsEachFrame(*parseAnimation("domain.radius=1:2", 5, error), base));
  EXPECT_TRUE(rebuildsEachFrame(*parseAnimation("octree.level=1:4", 5, error), base));
  // What --set refuses is refused with its message and the how-to: a plane the scene does
  // not have, a vector, a value out of range.
  for (const char* bad : {"clip.plane.2.offset=0:1", "camera.eye=0:1", "volume.density=-2:1"}) {
    const auto anim = parseAnimation(bad, 3, error);
    ASSERT_TRUE(anim) << bad;
    const std::string message = frameScene(*anim, base, 0, frame);
    EXPECT_NE(message.find("error:"), std::string::npos) << bad;
    EXPECT_NE(message.find("hint: write KEY=FROM:TO"), std::string::npos) << bad;
  }
}

TEST(Animation, OrbitTurnsTheEyeAboutUpThroughTheTarget) {
  Camera cam;
  cam.eye = {1, 2, 4};
  cam.target = {1, 0, 0};
  cam.up = {0, 2, 0};  // need not be unit length
  const Vec3 quarter = orbitEye(cam, 90);
  EXPECT_NEAR(quarter[0], 1 + 4, 1e-12);
  EXPECT_NEAR(quarter[1], 2, 1e-12) << "the height along up is kept";
  EXPECT_NEAR(quarter[2], 0, 1e-12);
  const Vec3 full = orbitEye(cam, 360);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(full[i], cam.eye[i], 1e-12);

  Scene base;
  base.render.camera = cam;
  std::string error;
  const auto anim = parseAnimation("camera.orbit=0:180", 3, error);
  Scene frame;
  ASSERT_EQ(frameScene(*anim, base, 2, frame), "");
  EXPECT_NEAR(frame.render.camera.eye[0], 1, 1e-12);
  EXPECT_NEAR(frame.render.camera.eye[2], -4, 1e-12);
  EXPECT_EQ(frame.render.camera.target, cam.target);
}

TEST(Animation, FrameNamesSortAndMatchTheFfmpegPattern) {
  EXPECT_EQ(frameFileName(0, 3), "frame-0000.png");
  EXPECT_EQ(frameFileName(42, 120), "frame-0042.png");
  EXPECT_EQ(frameFilePattern(120), "frame-%04d.png");
  EXPECT_EQ(frameFileName(7, 20000), "frame-00007.png") << "more frames, more digits";
  EXPECT_EQ(frameFilePattern(20000), "frame-%05d.png");
}

TEST(Video, FfmpegGetsTheFramesRatePaddingAndOutput) {
  const auto args = ffmpegArgs("/usr/bin/ffmpeg", "f/frame-%04d.png", "out.mp4", 24);
  const std::vector<std::string> expected{"/usr/bin/ffmpeg",
                                          "-y",
                                          "-loglevel",
                                          "error",
                                          "-framerate",
                                          "24",
                                          "-i",
                                          "f/frame-%04d.png",
                                          "-vf",
                                          "pad=ceil(iw/2)*2:ceil(ih/2)*2",
                                          "-pix_fmt",
                                          "yuv420p",
                                          "out.mp4"};
  EXPECT_EQ(args, expected);
  const auto gif = ffmpegArgs("ffmpeg", "p", "a.gif", 10);
  EXPECT_EQ(gif.back(), "a.gif");
  EXPECT_EQ(std::find(gif.begin(), gif.end(), "yuv420p"), gif.end());
}

TEST(Video, MissingFfmpegMessageSaysHowToGetItAndWhereTheFramesAre) {
  const std::string msg = missingFfmpegMessage("frames");
  EXPECT_NE(msg.find("error: --video needs ffmpeg"), std::string::npos);
  EXPECT_NE(msg.find("apt install ffmpeg"), std::string::npos);
  EXPECT_NE(msg.find("written to frames/ and"), std::string::npos);
  EXPECT_NE(missingFfmpegMessage("out/").find("written to out/ and"), std::string::npos);
}

TEST(PlayButton, SweepsUpTurnsAtTheTopAndComesBack) {
  int dir = 1;
  double v = 0.0;
  v = sweepStep(v, 0, 1, 1.0, 4.0, dir);  // a quarter of the range per second
  EXPECT_DOUBLE_EQ(v, 0.25);
  EXPECT_EQ(dir, 1);
  v = sweepStep(0.9, 0, 1, 1.0, 4.0, dir);  // would reach 1.15: reflected to 0.85
  EXPECT_NEAR(v, 0.85, 1e-12);
  EXPECT_EQ(dir, -1);
  v = sweepStep(0.1, 0, 1, 1.0, 4.0, dir);
  EXPECT_NEAR(v, 0.15, 1e-12);
  EXPECT_EQ(dir, 1);
  // A frame that took far too long never leaves the range.
  v = sweepStep(0.5, 0, 1, 100.0, 4.0, dir);
  EXPECT_GE(v, 0.0);
  EXPECT_LE(v, 1.0);
  // An empty range or no time: nothing moves.
  EXPECT_DOUBLE_EQ(sweepStep(0.3, 1, 1, 1.0, 4.0, dir), 0.3);
  EXPECT_DOUBLE_EQ(sweepStep(0.3, 0, 1, 0.0, 4.0, dir), 0.3);
}

}  // namespace
}  // namespace zs::app
