#pragma once
// Builds surfaces off the main thread, so a window never freezes: takes a session's build
// requests (session.hpp), runs Session::build (parse, octree, box hierarchy, GLSL, glslang:
// CPU only) on one worker thread, and puts out the finished surface or its error text,
// tagged with the request's id, for Session::finishBuild. An optional warm-up step runs on
// the same thread after each build: the front ends compile and draw the new shader there in
// a GL context of the worker's own, so the driver's shader cache holds the compiled program
// before the main thread asks for it (its compile then takes milliseconds, and the picture
// drawn meanwhile keeps moving). An optional later step runs after a result once no newer
// request has come for a moment. Latest wins: a request that has not started yet is
// replaced by a newer one, so dragging a slider queues at most one build behind the
// running one.
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <variant>

#include "session/session.hpp"

namespace zs::session {

class SurfaceWorker {
 public:
  struct Result {
    BuildResult build;
    double wallMs = 0;  // request to result, queueing included
  };

  // Runs on the worker thread after a build that succeeded, before its result is handed out.
  using WarmUp = std::function<void(const Scene&, const PreparedSurface&)>;

  // Runs on the worker thread after a build that succeeded, once its result is out and no
  // newer request has come for kLaterDelay: work that may wait for a pause in the requests
  // (the warm-up of the passes a picture takes once its program is in).
  using Later = std::function<void(const Scene&)>;
  static constexpr std::chrono::milliseconds kLaterDelay{500};

  // `wake` runs on the worker thread after each result (the viewer posts an empty GLFW
  // event so its event wait returns at once). `stop` runs on the worker thread as it ends
  // (the warm-up's GL objects and context are released on the thread they are current on).
  explicit SurfaceWorker(PrepareOptions options, std::function<void()> wake, WarmUp warmUp = {},
                         std::function<void()> stop = {}, Later later = {});
  ~SurfaceWorker();  // waits for a running build to finish; queued ones are dropped
  SurfaceWorker(const SurfaceWorker&) = delete;
  SurfaceWorker& operator=(const SurfaceWorker&) = delete;

  void submit(BuildRequest request);
  // The newest finished result not taken yet; older finished ones are dropped.
  std::optional<Result> take();
  bool busy() const;  // something queued or running

 private:
  void run();

  PrepareOptions options_;
  std::function<void()> wake_;
  WarmUp warmUp_;
  std::function<void()> stopHook_;
  Later later_;
  mutable std::mutex mutex_;
  std::condition_variable cv_;
  std::optional<BuildRequest> queued_;
  std::optional<Result> done_;
  bool running_ = false, stop_ = false;
  std::chrono::steady_clock::time_point queuedAt_;
  std::thread thread_;  // last member: starts after everything it touches exists
};

}  // namespace zs::session
