// `zeroset render --animate` end to end, headless: a few small frames of the Kummer family
// written as numbered PNGs, each the picture a single render with that parameter gives;
// camera-only animation keeping its octree; the video through ffmpeg where it is
// installed, and a clear refusal where it is not.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "app/animate/video.hpp"
#include "process.hpp"
#include "render/image.hpp"

namespace zs::test {
namespace {

namespace fs = std::filesystem;

fs::path example(const std::string& name) {
  const char* root = std::getenv("ZS_SOURCE_DIR");
  return fs::path(root ? root : ".") / "examples" / name;
}

// Runs zeroset with `args` (and environment changes), waits, returns the exit status and
// fills `output` with what it printed.
int runZeroset(const std::vector<std::string>& args, const fs::path& dir, std::string& output,
               const std::vector<EnvChange>& env = {}) {
  std::vector<std::string> argv{ZS_ZEROSET_EXE};
  argv.insert(argv.end(), args.begin(), args.end());
  const fs::path log = dir / "log.txt";
  fs::remove(log);
  Child c(argv, env, Stdio::File, log);
  const int status = c.wait(240);
  output = readText(log);
  return status;
}

Image load(const fs::path& path) {
  Image image;
  EXPECT_EQ(readPng(path.string(), image), "") << path;
  return image;
}

// `zeroset render --tile I/N` and `zeroset assemble`: the bands of a picture whose height is
// no multiple of the beam tile, stacked, are the whole picture pixel for pixel; a poster
// taller than a framebuffer renders band by band.
TEST(Tiles, BandsAssembleIntoExactlyTheWholePicture) {
  const fs::path dir = freshDir("tiles");
  const std::string formula = "x^2+y^2+z^2-1+0.2*sin(4x)*sin(4y)";
  std::string out;
  ASSERT_EQ(runZeroset({"render", formula, "--size", "97x83", "-o", (dir / "whole.png").string()},
                       dir, out),
            0)
      << out;
  std::vector<std::string> assemble{"assemble", "-o", (dir / "stacked.png").string()};
  for (int i = 0; i < 3; ++i) {
    const std::string band = (dir / ("band" + std::to_string(i) + ".png")).string();
    ASSERT_EQ(runZeroset({"render", formula, "--size", "97x83", "--tile", std::to_string(i) + "/3",
                          "-o", band},
                         dir, out),
              0)
        << out;
    assemble.push_back(band);
  }
  ASSERT_EQ(runZeroset(assemble, dir, out), 0) << out;
  const Image whole = load(dir / "whole.png"), stacked = load(dir / "stacked.png");
  ASSERT_EQ(stacked.width, whole.width);
  ASSERT_EQ(stacked.height, whole.height);
  EXPECT_TRUE(stacked.rgba == whole.rgba) << "the stacked bands differ from the whole picture";

  // Taller than any framebuffer (16384 rows): one band of it.
  ASSERT_EQ(runZeroset({"render", "x^2+y^2+z^2-1", "--size", "16x40000", "--tile", "2/5", "-o",
                        (dir / "tall.png").string()},
                       dir, out),
            0)
      << out;
  EXPECT_EQ(load(dir / "tall.png").height, 8000) << out;
  // Bands of different widths are refused.
  ASSERT_EQ(
      runZeroset({"render", "x", "--size", "40x32", "-o", (dir / "narrow.png").string()}, dir, out),
      0);
  EXPECT_NE(runZeroset({"assemble", "-o", (dir / "bad.png").string(), (dir / "whole.png").string(),
                        (dir / "narrow.png").string()},
                       dir, out),
            0);
  EXPECT_NE(out.find("one width"), std::string::npos) << out;
}

TEST(Animate, KummerFamilyFramesAreNumberedAndEachIsThatParametersPicture) {
  const fs::path dir = freshDir("animate_kummer");
  const fs::path frames = dir / "frames";
  std::string out;
  ASSERT_EQ(
      runZeroset({"render", example("kummer-quartic.surf").string(), "--animate",
                  "params.mu=1.0:1.6", "--frames", "3", "--size", "64x48", "-o", frames.string()},
                 dir, out),
      0)
      << out;
  for (int i = 0; i < 3; ++i)
    EXPECT_TRUE(fs::exists(frames / ("frame-000" + std::to_string(i) + ".png"))) << out;
  EXPECT_FALSE(fs::exists(frames / "frame-0003.png"));
  EXPECT_NE(out.find("params.mu = 1.3,"), std::string::npos) << out;
  EXPECT_NE(out.find("(rebuilt)"), std::string::npos) << "mu is in F: a new octree per frame";
  EXPECT_NE(out.find("octree rebuilt per frame"), std::string::npos) << out;

  const Image first = load(frames / "frame-0000.png");
  const Image middle = load(frames / "frame-0001.png");
  const Image last = load(frames / "frame-0002.png");
  EXPECT_EQ(first.width, 64);
  EXPECT_EQ(first.height, 48);
  EXPECT_FALSE(withinTolerance(compareImages(first, last))) << "the surface must change";

  // The middle frame is what a plain render with mu = 1.3 draws.
  const fs::path single = dir / "single.png";
  ASSERT_EQ(runZeroset({"render", example("kummer-quartic.surf").string(), "--set", "params.mu=1.3",
                        "--size", "64x48", "-o", single.string()},
                       dir, out),
            0)
      << out;
  EXPECT_TRUE(withinTolerance(compareImages(middle, load(single)))) << "frame 1 is mu = 1.3";
}

// A level sweep, of the first surface or of a second one: each frame is the picture a
// plain render at that level gives (the level is part of F, so the shader changes too).
TEST(Animate, LevelFramesAreEachThatLevelsPicture) {
  const fs::path dir = freshDir("animate_level");
  for (const std::string key : {"surface.level", "surface.2.level"}) {
    const fs::path frames = dir / (key == "surface.level" ? "first" : "second");
    std::string out;
    ASSERT_EQ(
        runZeroset({"render", "x^2+y^2+z^2-1", "--surface", "z-0.25", "--animate",
                    key + "=-0.5:0.5", "--frames", "3", "--size", "64x48", "-o", frames.string()},
                   dir, out),
        0)
        << out;
    const Image first = load(frames / "frame-0000.png");
    const Image last = load(frames / "frame-0002.png");
    EXPECT_FALSE(withinTolerance(compareImages(first, last))) << key << ": the surface must change";
    const fs::path single = dir / "single.png";
    ASSERT_EQ(runZeroset({"render", "x^2+y^2+z^2-1", "--surface", "z-0.25", "--set", key + "=0.5",
                          "--size", "64x48", "-o", single.string()},
                         dir, out),
              0)
        << out;
    EXPECT_TRUE(withinTolerance(compareImages(last, load(single)))) << key << ": frame 2 is 0.5";
  }
}

TEST(Animate, CameraOrbitKeepsOneOctree) {
  const fs::path dir = freshDir("animate_orbit");
  std::string out;
  ASSERT_EQ(runZeroset(
                {"render", example("dupin-cyclide.surf").string(), "--animate", "camera.orbit=0:90",
                 "--frames", "2", "--size", "48x36", "-o", (dir / "orbit").string()},
                dir, out),
            0)
      << out;
  EXPECT_EQ(out.find("(rebuilt)"), std::string::npos) << out;
  EXPECT_NE(out.find("octree built once"), std::string::npos) << out;
  EXPECT_FALSE(withinTolerance(compareImages(load(dir / "orbit" / "frame-0000.png"),
                                             load(dir / "orbit" / "frame-0001.png"))))
      << "the camera moved";
}

TEST(Animate, VideoIsEncodedWhenFfmpegIsInstalled) {
  if (!app::findFfmpeg()) GTEST_SKIP() << "ffmpeg is not installed";
  const fs::path dir = freshDir("animate_video");
  std::string out;
  const fs::path video = dir / "kummer.mp4";
  ASSERT_EQ(runZeroset({"render", example("kummer-quartic.surf").string(), "--animate",
                        "params.mu=1.0:1.6", "--frames", "4", "--size", "63x47", "-o",
                        (dir / "frames").string(), "--video", video.string(), "--fps", "10"},
                       dir, out),
            0)
      << out;
  ASSERT_TRUE(fs::exists(video)) << out;
  EXPECT_GT(fs::file_size(video), 0u);
}

// With a stand-in ffmpeg on the PATH (a script that checks its input and writes the output),
// the hand-over itself is tested on every machine: the frames exist when it runs, the
// pattern names them, and the rate and output are passed through.
TEST(Animate, VideoHandsTheFramePatternToFfmpegOnThePath) {
  const fs::path dir = freshDir("animate_fake_ffmpeg");
  const fs::path bin = dir / "bin";
  fs::create_directories(bin);
  const fs::path fake = bin / "ffmpeg";
  std::ofstream(fake) << "#!/bin/sh\n"
                         "echo \"$@\" > \"${0%/*}/args.txt\"\n"
                         "for a; do last=$a; done\n"
                         "[ -f \"${0%/*}/../frames/frame-0001.png\" ] || exit 3\n"
                         "echo video > \"$last\"\n";
  fs::permissions(fake, fs::perms::owner_all);
  std::string out;
  const fs::path video = dir / "k.mp4";
  ASSERT_EQ(runZeroset({"render", "x^2 + y^2 + z^2 - r", "--animate", "params.r=0.5:1", "--frames",
                        "2", "--size", "16x12", "-o", (dir / "frames").string(), "--video",
                        video.string(), "--fps", "12"},
                       dir, out, {{"PATH", bin.string()}}),
            0)
      << out;
  EXPECT_EQ(readText(video), "video\n");
  const std::string args = readText(bin / "args.txt");
  EXPECT_NE(args.find("-framerate 12 -i " + (dir / "frames" / "frame-%04d.png").string()),
            std::string::npos)
      << args;
  EXPECT_NE(out.find("wrote " + video.string() + " (2 frames at 12 fps)"), std::string::npos)
      << out;
}

TEST(Animate, VideoWithoutFfmpegIsRefusedBeforeRendering) {
  const fs::path dir = freshDir("animate_no_ffmpeg");
  const fs::path emptyPath = dir / "bin";
  fs::create_directories(emptyPath);
  std::string out;
  EXPECT_EQ(runZeroset({"render", example("kummer-quartic.surf").string(), "--animate",
                        "params.mu=1.0:1.6", "--frames", "2", "--size", "32x24", "-o",
                        (dir / "frames").string(), "--video", (dir / "k.mp4").string()},
                       dir, out, {{"PATH", emptyPath.string()}}),
            1);
  EXPECT_NE(out.find("error: --video needs ffmpeg"), std::string::npos) << out;
  EXPECT_NE(out.find("hint: install it"), std::string::npos) << out;
  EXPECT_FALSE(fs::exists(dir / "frames" / "frame-0000.png"));
}

TEST(Animate, BadSpecsAndStrayOptionsAreErrorsWithHints) {
  const fs::path dir = freshDir("animate_errors");
  std::string out;
  EXPECT_EQ(
      runZeroset({"render", "x^2+y^2+z^2-a", "--animate", "params.a=1", "-o", (dir / "f").string()},
                 dir, out),
      1);
  EXPECT_NE(out.find("hint: write KEY=FROM:TO"), std::string::npos) << out;
  EXPECT_NE(runZeroset({"render", "x^2+y^2+z^2-1", "--frames", "3", "-o", "x.png"}, dir, out), 0)
      << "--frames needs --animate";
  // -o names a PNG: surely a mistake, refused before anything is made.
  EXPECT_EQ(runZeroset({"render", "x^2+y^2+z^2-a", "--animate", "params.a=0.5:1", "-o",
                        (dir / "one.png").string()},
                       dir, out),
            1);
  EXPECT_NE(out.find("-o names the folder of the frames"), std::string::npos) << out;
  EXPECT_FALSE(fs::exists(dir / "one.png"));
  // -o names an existing file: it cannot be the folder of frames.
  std::ofstream(dir / "taken") << "x";
  EXPECT_EQ(runZeroset({"render", "x^2+y^2+z^2-a", "--animate", "params.a=0.5:1", "--frames", "2",
                        "--size", "16x12", "-o", (dir / "taken").string()},
                       dir, out),
            1);
  EXPECT_NE(out.find("-o names a folder"), std::string::npos) << out;
}

}  // namespace
}  // namespace zs::test
