#include "app/print_job.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <variant>

#include "pipeline/load_surface.hpp"
#include "pipeline/pipeline.hpp"
#include "render/ray_tracer.hpp"
#include "scene/description.hpp"
#include "scene/scene_io.hpp"

namespace zs::app {

std::string runPrintJob(const PrintJob& job) {
  if (!printing::isPageFile(job.output))
    return "print: " + job.output.string() + ": the page is written as .pdf or .svg\n";
  Scene scene = job.scene;
  // A square picture as wide as the page's text, at the asked resolution.
  const int side = int(std::lround(printing::pictureSide(job.paper) / 72.0 * job.dpi));
  if (side < 16 || side > 16384) {
    return "print: a picture of " + std::to_string(side) +
           " pixels a side is out of range\n"
           "hint: a lower --dpi, or a smaller paper\n";
  }
  scene.width = scene.height = side;
  auto prepared = prepareSurface(scene);
  if (auto* err = std::get_if<std::string>(&prepared)) return *err;
  const PreparedSurface& surface = std::get<PreparedSurface>(prepared);
  HeadlessTracer gl = openHeadlessTracer(job.backend, surface, scene.render);
  if (!gl.tracer) return "print: no GL context for the picture (see above)\n";
  // The tracer draws in tiles, so a large picture never holds the GPU for long.
  Frame frame = gl.tracer->render(scene.render, scene.domain, side, side);
  if (!frame.error.empty()) return "print: " + frame.error + "\n";

  printing::PageContent page;
  page.picture = std::move(frame.color);
  page.title = job.title;
  page.description = job.description;
  for (std::size_t i = 0; i < surfaceCount(scene); ++i) {
    const SurfaceEntry surface = surfaceAt(scene, i);
    page.formulas.emplace_back(surface.formula, surface.level);
  }
  if (auto parsed = parseSceneFormula(scene); std::holds_alternative<Formula>(parsed)) {
    const Graph& graph = std::get<Formula>(parsed).graph;
    const std::vector<double> values = paramValues(scene, graph);
    for (std::size_t i = 0; i < values.size(); ++i)
      page.params.emplace_back(graph.params()[i], values[i]);
  }
  if (std::string err = printing::writePage(job.output, page, job.paper); !err.empty())
    return err + "\n";
  return "";
}

void describeForPrint(const std::string& input, std::string& title, std::string& description) {
  title = "zeroset";
  description.clear();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(input, ec)) return;
  title = std::filesystem::path(input).stem().string();
  std::ifstream file(input);
  std::stringstream text;
  text << file.rdbuf();
  const std::string summary = summaryLine(text.str());
  const std::string dash = " \u2014 ";
  if (const std::size_t at = summary.find(dash); at != std::string::npos) {
    title = summary.substr(0, at);
    description = summary.substr(at + dash.size());
  } else {
    description = summary;
  }
}

}  // namespace zs::app
