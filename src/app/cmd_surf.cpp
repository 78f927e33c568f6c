// `zeroset surf [-n] [-q|--quiet|--silent] FILE...`: runs surf scripts as surf 1.0.6 does and
// writes the pictures each one saves (save_color_image, in its color_file_format: jpg, ppm,
// sun or zeroset's png). zeroset run under the name surf, surf-alggeo or surf-alggeo-nox is
// this command, with surf's own command line; run as surfer it shows a SURFER file (main.cpp,
// docs/surf.md). Unlike surf, an error stops with file:line:column and a non-zero status.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>

#include "app/commands.hpp"
#include "curve/curve.hpp"
#include "parser/parser.hpp"
#include "pipeline/load_surface.hpp"
#include "pipeline/pipeline.hpp"
#include "render/gl_context.hpp"
#include "render/image_formats.hpp"
#include "render/ray_tracer.hpp"
#include "scene/scene_io.hpp"
#include "surfscript/surf_import.hpp"

namespace zs::app {

namespace {

PictureFormat pictureFormat(surfscript::ImageFormat f) {
  switch (f) {
    case surfscript::ImageFormat::Jpeg:
      return PictureFormat::Jpeg;
    case surfscript::ImageFormat::Ppm:
      return PictureFormat::Ppm;
    case surfscript::ImageFormat::Png:
      return PictureFormat::Png;
    default:
      return PictureFormat::Sun;
  }
}

// The surfaces of a picture, or surf's empty buffer (black) where it has none.
std::string drawSurfaces(const Scene& scene, Image& out) {
  if (scene.formula.empty()) {
    out.width = scene.width;
    out.height = scene.height;
    out.rgba.assign(std::size_t(out.width) * out.height * 4, 0);
    for (std::size_t i = 3; i < out.rgba.size(); i += 4) out.rgba[i] = 255;
    return {};
  }
  // Without glslang's check: the driver compiles the shader anyway and reports what it
  // refuses (briefly, with the details in a file), and glslang's start-up is a fifth of a
  // small picture's whole time (docs/surf-scripts.md, Speed).
  auto prepared = prepareSurface(scene, kWithoutGlslang);
  if (auto* err = std::get_if<std::string>(&prepared)) return *err;
  const PreparedSurface& surface = std::get<PreparedSurface>(prepared);
  preferQuickShaderCompile(double(scene.width) * scene.height * scene.render.samples *
                           scene.render.samples);
  HeadlessTracer gl = openHeadlessTracer(Backend::Egl, surface, scene.render);
  if (!gl.tracer) return "no GL context to draw with";
  Frame frame = gl.tracer->render(scene.render, scene.domain, scene.width, scene.height);
  if (!frame.error.empty()) return frame.error;
  out = std::move(frame.color);
  return {};
}

// surf's draw_curve over the picture, exactly (src/curve).
std::string drawCurve(const surfscript::ScriptCurve& c, Image& image) {
  const ParseResult parsed = parseFormula(c.formula);
  if (const auto* err = std::get_if<ParseError>(&parsed)) return formatError(c.formula, *err);
  const Formula& f = std::get<Formula>(parsed);
  curve::CurveOptions options;
  options.halfWidth = c.halfWidth;
  const curve::CurveMask mask =
      curve::rasterizeCurve(f.graph, f.root, c.map, image.width, image.height, options);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      if (!mask.drawn[std::size_t(y) * image.width + x]) continue;
      if (c.clipped) {
        const double u = c.u0 + c.du * x - c.discU, v = c.v0 + c.dv * y - c.discV;
        if (u * u + v * v > c.discRadius * c.discRadius) continue;
      }
      std::uint8_t* p = image.pixel(x, y);
      for (int k = 0; k < 3; ++k)
        p[k] = static_cast<std::uint8_t>(std::lround(std::clamp(c.color[k], 0.0, 1.0) * 255));
    }
  }
  return {};
}

// One picture of a script to its file; "" or why not.
std::string drawPicture(const surfscript::ScriptPicture& p) {
  Image image;
  if (std::string err = drawSurfaces(p.scene, image); !err.empty()) return err;
  for (const surfscript::ScriptCurve& c : p.curves)
    if (std::string err = drawCurve(c, image); !err.empty()) return err;
  return writePicture(p.fileName, image, pictureFormat(p.format));
}

int runScriptFile(const std::string& file, bool quiet) {
  auto text = readSceneFile(file, "surf script");
  if (auto* err = std::get_if<SceneError>(&text)) {
    std::cerr << formatSceneError(*err);
    return 1;
  }
  if (!quiet) std::printf("zeroset: executing %s\n", file.c_str());
  auto run = surfscript::runSurfScript(std::get<std::string>(text), file);
  if (auto* err = std::get_if<SceneError>(&run)) {
    std::cerr << formatSceneError(*err);
    return 1;
  }
  const auto& pictures = std::get<surfscript::ScriptPictures>(run);
  if (!quiet)
    for (const SceneError& w : pictures.warnings) std::cerr << formatSceneWarning(w);
  for (const surfscript::ScriptPicture& p : pictures.pictures) {
    if (std::string err = drawPicture(p); !err.empty()) {
      SceneError e = p.place;
      e.message = "save_color_image: " + err;
      std::cerr << formatSceneError(e);
      return 1;
    }
    if (!quiet)
      std::printf("wrote %s (%dx%d)\n", p.fileName.c_str(), p.scene.width, p.scene.height);
  }
  return 0;
}

int runScripts(const std::vector<std::string>& files, bool quiet) {
  for (const std::string& f : files)
    if (int rc = runScriptFile(f, quiet); rc != 0) return rc;
  return 0;
}

const char* const kSurfUsage =
    "usage: surf [-n] [-q|--quiet|--silent] FILE...\n"
    "  runs surf scripts with zeroset, writing the pictures they save (docs/surf.md)\n";

}  // namespace

int runSurfCommandLine(const std::vector<std::string>& args) {
  bool quiet = false;
  std::vector<std::string> files;
  for (const std::string& a : args) {
    if (a == "-q" || a == "--quiet" || a == "--silent")
      quiet = true;
    else if (a == "-n" || a == "--no-gui" || a == "-v" || a == "--enable-auto-extension" ||
             a == "--disable-auto-extension")
      continue;  // surf's: no window here anyway; zeroset never renames the pictures
    else if (a == "-h" || a == "--help") {
      std::cout << kSurfUsage;
      return 0;
    } else if (!a.empty() && a[0] == '-' && a != "-") {
      std::cerr << "surf: unknown option " << a << "\n" << kSurfUsage;
      return 1;
    } else {
      files.push_back(a);
    }
  }
  if (files.empty()) {
    std::cerr << "surf: no script given (zeroset has no surf window: name the scripts to run)\n"
              << kSurfUsage;
    return 1;
  }
  return runScripts(files, quiet);
}

void addSurfCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "surf", "Run surf scripts (.pic), writing the pictures they save, as surf does");
  auto files = std::make_shared<std::vector<std::string>>();
  auto quiet = std::make_shared<bool>(false);
  cmd->add_option("files", *files, "the surf scripts, run in order")->required();
  cmd->add_flag("-q,--quiet", *quiet, "print nothing but errors");
  cmd->callback([files, quiet] { std::exit(runScripts(*files, *quiet)); });
}

}  // namespace zs::app
