// The `surf` command as Singular and a user run it: zeroset under surf's name (build/compat)
// writes the pictures a script saves, refuses a bad script without writing anything, draws
// what surf 1.0.6 draws (Debian's surf-alggeo-nox, side by side), and answers Singular's
// plot, plot_jupyter and surfer from its unmodified libraries.
#include <gtest/gtest.h>
#include <jpeglib.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "process.hpp"
#include "render/image.hpp"

namespace zs::test {
namespace {

namespace fs = std::filesystem;

const fs::path kCompat = ZS_COMPAT_DIR;
const fs::path kData = ZS_SURF_TEST_DATA;

void writeText(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

bool onPath(const std::string& program) {
  return shell("command -v " + program + " > /dev/null 2>&1") == 0;
}

// P6 files, as both surfs write them.
bool readPpm(const fs::path& path, Image& out) {
  std::ifstream in(path, std::ios::binary);
  std::string magic;
  int w = 0, h = 0, max = 0;
  if (!(in >> magic >> w >> h >> max) || magic != "P6" || max != 255 || w <= 0 || h <= 0)
    return false;
  in.get();
  std::string rgb(std::size_t(w) * h * 3, '\0');
  if (!in.read(rgb.data(), std::streamsize(rgb.size()))) return false;
  out.width = w;
  out.height = h;
  out.rgba.resize(std::size_t(w) * h * 4);
  for (std::size_t i = 0; i < std::size_t(w) * h; ++i) {
    for (int c = 0; c < 3; ++c) out.rgba[i * 4 + c] = static_cast<std::uint8_t>(rgb[i * 3 + c]);
    out.rgba[i * 4 + 3] = 255;
  }
  return true;
}

bool readJpeg(const fs::path& path, Image& out) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return false;
  jpeg_decompress_struct info{};
  jpeg_error_mgr err{};
  info.err = jpeg_std_error(&err);
  jpeg_create_decompress(&info);
  jpeg_stdio_src(&info, f);
  const bool ok = jpeg_read_header(&info, TRUE) == JPEG_HEADER_OK;
  if (ok) {
    info.out_color_space = JCS_RGB;
    jpeg_start_decompress(&info);
    out.width = int(info.output_width);
    out.height = int(info.output_height);
    out.rgba.assign(std::size_t(out.width) * out.height * 4, 255);
    std::vector<unsigned char> row(std::size_t(out.width) * 3);
    while (info.output_scanline < info.output_height) {
      const int y = int(info.output_scanline);
      JSAMPROW r = row.data();
      jpeg_read_scanlines(&info, &r, 1);
      for (int x = 0; x < out.width; ++x)
        for (int c = 0; c < 3; ++c) out.pixel(x, y)[c] = row[std::size_t(x) * 3 + c];
    }
    jpeg_finish_decompress(&info);
  }
  jpeg_destroy_decompress(&info);
  std::fclose(f);
  return ok;
}

struct SideBySide {
  double outlineMismatch = 1;    // pixels that are surface in one picture, background in the other
  double colorDifference = 255;  // mean channel difference where both show the surface
};

// Surface or background by the distance from the corner pixel's colour (the background).
SideBySide compare(const Image& a, const Image& b) {
  SideBySide out;
  if (a.width != b.width || a.height != b.height) return out;
  const std::uint8_t* bg = a.pixel(0, 0);
  auto isSurface = [&](const std::uint8_t* p) {
    return std::max({std::abs(p[0] - bg[0]), std::abs(p[1] - bg[1]), std::abs(p[2] - bg[2])}) > 12;
  };
  std::size_t mismatch = 0, both = 0;
  double difference = 0;
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      const bool sa = isSurface(a.pixel(x, y)), sb = isSurface(b.pixel(x, y));
      if (sa != sb)
        ++mismatch;
      else if (sa) {
        ++both;
        for (int c = 0; c < 3; ++c)
          difference += std::abs(a.pixel(x, y)[c] - b.pixel(x, y)[c]) / 3.0;
      }
    }
  }
  out.outlineMismatch = double(mismatch) / (double(a.width) * a.height);
  out.colorDifference = both ? difference / double(both) : 0;
  return out;
}

// What the run printed after `label` on its line, or "" when it did not print the label.
std::string printed(const std::string& out, const std::string& label) {
  const std::size_t at = out.find(label);
  if (at == std::string::npos) return {};
  const std::size_t from = at + label.size();
  return out.substr(from, out.find('\n', from) - from);
}

std::string runIn(const fs::path& dir, const std::string& command) {
  const fs::path log = dir / "command.log";
  const int rc = shell("cd " + dir.string() + " && " + command + " > " + log.string() + " 2>&1");
  return std::to_string(rc) + "\n" + readText(log);
}

TEST(SurfCommand, WritesThePicturesAScriptSaves) {
  const fs::path dir = freshDir("surf-pictures");
  writeText(dir / "three.pic",
            "width = 64; height = 48; surface = x^2 + y^2 + z^2 - 25; draw_surface;\n"
            "filename = \"one.jpg\"; color_file_format = jpg; save_color_image;\n"
            "filename = \"two.ppm\"; color_file_format = ppm; save_color_image;\n"
            "clear_screen; surface = x*y*z - 2; draw_surface;\n"
            "filename = \"three.png\"; color_file_format = png; save_color_image;\n");
  const std::string out = runIn(dir, (kCompat / "surf").string() + " -q three.pic");
  ASSERT_EQ(out.substr(0, 2), "0\n") << out;
  Image jpg, ppm, png;
  ASSERT_TRUE(readJpeg(dir / "one.jpg", jpg));
  ASSERT_TRUE(readPpm(dir / "two.ppm", ppm));
  ASSERT_EQ(readPng((dir / "three.png").string(), png), "");
  EXPECT_EQ(jpg.width, 64);
  EXPECT_EQ(jpg.height, 48);
  EXPECT_EQ(ppm.width, 64);
  // The same drawing in two formats; the third is another surface.
  EXPECT_LT(compare(ppm, jpg).colorDifference, 6);
  EXPECT_GT(compare(ppm, png).outlineMismatch, 0.05);
  EXPECT_FALSE(fs::exists(dir / "one.jpg.zeroset-tmp")) << "no temporary left behind";
}

TEST(SurfCommand, ABadScriptWritesNothingAndSaysWhere) {
  const fs::path dir = freshDir("surf-bad");
  writeText(dir / "bad.pic",
            "surface = x^2 + y^2 - 1; draw_surface;\n"
            "filename = \"early.jpg\"; color_file_format = jpg; save_color_image;\n"
            "surface_redd = 255;\n");
  const std::string out = runIn(dir, (kCompat / "surf-alggeo").string() + " bad.pic");
  EXPECT_NE(out.substr(0, 2), "0\n") << out;
  EXPECT_NE(out.find("bad.pic:3:1: error: unknown variable 'surface_redd'"), std::string::npos)
      << out;
  EXPECT_NE(out.find("did you mean surface_red?"), std::string::npos) << out;
  EXPECT_FALSE(fs::exists(dir / "early.jpg"))
      << "the script is checked whole before a picture is drawn";
}

// Side by side with surf 1.0.6 (Debian's surf-alggeo-nox) on scripts of each kind: the
// same outline, the colours within surf's depth cueing, which zeroset does not draw.
TEST(SurfCommand, DrawsWhatSurfDraws) {
  ASSERT_TRUE(onPath("surf-alggeo-nox")) << "scripts/install-deps.sh installs surf-alggeo-nox";
  // surf shades a curve's edge pixels grey (antialiased); zeroset draws them whole.
  const std::pair<const char*, double> scripts[] = {{"cone_turned", 40},
                                                    {"kummer_camera", 40},
                                                    {"plane_in_cube", 40},
                                                    {"two_surfaces", 40},
                                                    {"curves", 80}};
  for (const auto& [name, colorTolerance] : scripts) {
    const fs::path dir = freshDir(std::string("surf-peer-") + name);
    fs::copy_file(kData / (std::string(name) + ".pic"), dir / "script.pic");
    const std::string surf =
        runIn(dir, "surf-alggeo-nox -q script.pic && mv " + std::string(name) + ".ppm surf.ppm");
    ASSERT_EQ(surf.substr(0, 2), "0\n") << surf;
    const std::string ours = runIn(dir, (kCompat / "surf").string() + " -q script.pic");
    ASSERT_EQ(ours.substr(0, 2), "0\n") << ours;
    Image theirs, mine;
    ASSERT_TRUE(readPpm(dir / "surf.ppm", theirs)) << name;
    ASSERT_TRUE(readPpm(dir / (std::string(name) + ".ppm"), mine)) << name;
    const SideBySide s = compare(theirs, mine);
    EXPECT_LT(s.outlineMismatch, 0.01) << name;
    EXPECT_LT(s.colorDifference, colorTolerance) << name;
  }
}

// The import is exact: a script's picture is the picture of the .surf scene zeroset import
// writes of it (the formula as written, the camera turned instead).
TEST(SurfCommand, TheImportedSceneDrawsTheScriptsPicture) {
  const fs::path zeroset = fs::read_symlink(kCompat / "surf");
  for (const char* name : {"cone_turned", "kummer_camera", "plane_in_cube"}) {
    const fs::path dir = freshDir(std::string("surf-import-") + name);
    const std::string script = (kData / (std::string(name) + ".pic")).string();
    const std::string out =
        runIn(dir, zeroset.string() + " render " + script + " -o direct.png && " +
                       zeroset.string() + " import " + script + " -o scene.surf && " +
                       zeroset.string() + " render scene.surf -o imported.png");
    ASSERT_EQ(out.substr(0, 2), "0\n") << out;
    Image direct, imported;
    ASSERT_EQ(readPng((dir / "direct.png").string(), direct), "");
    ASSERT_EQ(readPng((dir / "imported.png").string(), imported), "");
    EXPECT_TRUE(withinTolerance(compareImages(direct, imported), 0.0, 0.0)) << name;
  }
}

// Singular's own libraries, unchanged, with build/compat first on PATH.
class SingularCalls : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(onPath("Singular")) << "scripts/install-deps.sh installs singular";
    dir_ = freshDir("singular");
    // surf.lib's plot shows its picture with the first of mimeopen, xdg-open, ...: this one
    // keeps it, since plot removes it afterwards.
    fs::create_directories(dir_ / "bin");
    writeText(dir_ / "bin" / "mimeopen",
              "#!/bin/sh\ncp \"$1\" " + (dir_ / "shown.jpg").string() + "\n");
    fs::permissions(dir_ / "bin" / "mimeopen", fs::perms::owner_all);
  }

  std::string singular(const std::string& script) {
    writeText(dir_ / "run.sing", script + "\nquit;\n");
    // singularsurf_jupyter, plot_jupyter's helper, lives in Singular's libexec folder.
    const std::string path = kCompat.string() + ":" + (dir_ / "bin").string() +
                             ":/usr/libexec/x86_64-linux-gnu/singular/MOD:$PATH";
    return runIn(dir_, "env -u DISPLAY -u WAYLAND_DISPLAY PATH=" + path + " Singular -q run.sing");
  }

  fs::path dir_;
};

TEST_F(SingularCalls, PlotShowsZerosetsPicturesOfASurfaceAndACurve) {
  const std::string out = singular(
      "LIB \"surf.lib\"; ring r = 0, (x,y,z), dp; poly f = x^2*y^2 + y^2*z^2 + z^2*x^2 - 1/2; "
      "plot(f);");
  ASSERT_EQ(out.substr(0, 2), "0\n") << out;
  EXPECT_EQ(out.find("failed"), std::string::npos) << out;
  Image shown;
  ASSERT_TRUE(readJpeg(dir_ / "shown.jpg", shown)) << out;
  EXPECT_EQ(shown.width, 500);
  // The script surf.lib writes (Singular 4.3's, as it is), drawn by zeroset directly.
  writeText(dir_ / "same.pic",
            "root_finder=d_chain_bisection;epsilon=0.0000000001;iterations=20000;\n"
            "width=500; height=500; set_size; do_background=yes; background_red=255; "
            "background_green=255; background_blue=255;\nrot_x=0.14; rot_y=-0.3;\nsurface=\n"
            "x^2*y^2+x^2*z^2+y^2*z^2-1/2\n;\ndraw_surface;\ncolor_file_format = jpg;\n"
            "filename = \"same.jpg\";\nsave_color_image;\n");
  ASSERT_EQ(runIn(dir_, (kCompat / "surf").string() + " -q same.pic").substr(0, 2), "0\n");
  Image same;
  ASSERT_TRUE(readJpeg(dir_ / "same.jpg", same));
  const SideBySide s = compare(same, shown);
  EXPECT_LT(s.outlineMismatch, 0.001);
  EXPECT_LT(s.colorDifference, 2);
  EXPECT_GT(
      compare(same, Image{500, 500, std::vector<std::uint8_t>(500 * 500 * 4, 255)}).outlineMismatch,
      0.02)
      << "the picture shows the surface (its thin arms reach out to surf's clip sphere)";

  // One test for both: plot writes and removes the one /tmp/surf.jpg, so two such tests
  // side by side under ctest -j would race.
  fs::remove(dir_ / "shown.jpg");
  {
    // Two variables: surf.lib sends a curve (draw_curve), red on surf's black buffer.
    const std::string curveOut =
        singular("LIB \"surf.lib\"; ring r = 0, (x,y), dp; poly f = y^2 - x^3 + 2*x - 1; plot(f);");
    ASSERT_EQ(curveOut.substr(0, 2), "0\n") << curveOut;
    Image curve;
    ASSERT_TRUE(readJpeg(dir_ / "shown.jpg", curve)) << curveOut;
    EXPECT_EQ(curve.width, 500);
    int red = 0;
    for (int y = 0; y < curve.height; ++y)
      for (int x = 0; x < curve.width; ++x) {
        const std::uint8_t* p = curve.pixel(x, y);
        red += p[0] > 150 && p[1] < 80 && p[2] < 80;
      }
    EXPECT_GT(red, 500) << "the curve crosses the picture";
  }
}

TEST_F(SingularCalls, PlotJupyterReturnsThePicture) {
  const std::string out = singular(
      "LIB \"surf_jupyter.lib\"; ring r = 0, (x,y,z), dp; poly f = x^2 + y^2 - z^2 - 1/4;"
      "string file = plot_jupyter(f); print(\"picture: \" + file);");
  ASSERT_EQ(out.substr(0, 2), "0\n") << out;
  const fs::path file = printed(out, "picture: ");
  ASSERT_FALSE(file.empty()) << out;
  Image picture;
  ASSERT_TRUE(readJpeg(file, picture)) << out;
  fs::remove(file);
  EXPECT_EQ(picture.width, 500);
}

TEST_F(SingularCalls, SurferShowsTheSurfaceWithoutADisplayAsAPicture) {
  const std::string out = singular(
      "LIB \"surf.lib\"; ring r = 0, (x,y,z), dp; poly f = x^3 + y^3 + z^3 - 1;"
      "print(\"pid: \" + string(system(\"pid\"))); surfer(f);");
  ASSERT_EQ(out.substr(0, 2), "0\n") << out;
  const std::string pid = printed(out, "pid: ");
  ASSERT_FALSE(pid.empty()) << out;
  const fs::path picture = "/tmp/surfer" + pid + ".png";
  Image png;
  ASSERT_EQ(readPng(picture.string(), png), "") << out;
  fs::remove(picture);
  EXPECT_GT(png.width, 0);
}

}  // namespace
}  // namespace zs::test
