// "Print page" (the panel's button, Ctrl+P): the shown scene as a printed page (PDF, A4,
// print/page.hpp) in the output folder, rendered and written on a thread of its own with
// its own headless GL context, so the window stays live. The path is printed on stdout as
// "printed: PATH".
#include <GLFW/glfw3.h>

#include "app/print_job.hpp"
#include "app/repl/scene_edit.hpp"
#include "app/viewer/viewer.hpp"
#include "i18n/translate.hpp"

namespace zs::app {

void Viewer::startPrint() {
  if (print_.valid()) {
    stats_.status = i18n::tr("a page is still printing");
    return;
  }
  PrintJob job;
  job.scene = session_.scene();
  // The file's name and description only while its formula is the one shown.
  const bool fromFile =
      !sceneFile_.empty() && session_.scene().formula == session_.loadedScene().formula;
  describeForPrint(fromFile ? sceneFile_.string() : "", job.title, job.description);
  const std::string stem = fromFile ? sceneFile_.stem().string() : "zeroset";
  job.output = nextFreePath(options_.outputDir, stem + "-page", ".pdf");
  stats_.status = i18n::tr("printing a page...");
  print_ = std::async(std::launch::async, [job] {
    const std::string error = runPrintJob(job);
    glfwPostEmptyEvent();  // wake the loop to show it
    if (!error.empty()) return FileJobResult{error, panelError(error)};
    return FileJobResult{"printed: " + job.output.string() + "\n",
                         i18n::format(i18n::tr("printed: %s"), job.output.string().c_str())};
  });
}

void Viewer::finishPrint() {
  finishFileJob(print_);
}

}  // namespace zs::app
