#pragma once
// One printed page of a scene (docs/print.md), for `zeroset print` and the viewer's Print
// button: takes the scene, its name and description, the paper and the resolution; renders
// the picture headless (its own GL context, so the viewer runs it on a thread of its own)
// and writes the page (print/page.hpp).
#include <filesystem>
#include <string>

#include "print/page.hpp"
#include "render/gl_context.hpp"
#include "scene/scene.hpp"

namespace zs::app {

struct PrintJob {
  Scene scene;
  std::string title, description;
  printing::Paper paper = printing::Paper::A4;
  double dpi = 300;              // of the picture on the page
  std::filesystem::path output;  // .pdf or .svg
  Backend backend = Backend::Egl;
};

// "" or the error, with a hint where there is one.
std::string runPrintJob(const PrintJob& job);

// The name and description a page shows for the scene loaded from `input`: a file's
// description line "NAME — REST" (examples/README.md) gives both; otherwise the file's
// name, or for a formula "zeroset", and no description.
void describeForPrint(const std::string& input, std::string& title, std::string& description);

}  // namespace zs::app
