// One long-lived worker thread; the octree itself fans out over every core.
#include "session/surface_worker.hpp"

#include <chrono>

namespace zs::session {

SurfaceWorker::SurfaceWorker(PrepareOptions options, std::function<void()> wake, WarmUp warmUp,
                             std::function<void()> stop, Later later)
    : options_(std::move(options)),
      wake_(std::move(wake)),
      warmUp_(std::move(warmUp)),
      stopHook_(std::move(stop)),
      later_(std::move(later)),
      thread_([this] { run(); }) {}

SurfaceWorker::~SurfaceWorker() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
    queued_.reset();
  }
  cv_.notify_all();
  thread_.join();
}

void SurfaceWorker::submit(BuildRequest request) {
  {
    std::lock_guard lock(mutex_);
    queued_ = std::move(request);
    queuedAt_ = std::chrono::steady_clock::now();
  }
  cv_.notify_all();
}

std::optional<SurfaceWorker::Result> SurfaceWorker::take() {
  std::lock_guard lock(mutex_);
  std::optional<Result> out = std::move(done_);
  done_.reset();
  return out;
}

bool SurfaceWorker::busy() const {
  std::lock_guard lock(mutex_);
  return running_ || queued_.has_value();
}

void SurfaceWorker::run() {
  std::unique_lock lock(mutex_);
  for (;;) {
    cv_.wait(lock, [this] { return stop_ || queued_.has_value(); });
    if (stop_) {
      lock.unlock();
      if (stopHook_) stopHook_();
      return;
    }
    BuildRequest request = std::move(*queued_);
    queued_.reset();
    const auto start = queuedAt_;
    running_ = true;
    lock.unlock();
    auto surface = Session::build(request, options_);
    request.base.reset();  // the surface on screen is not held here longer than needed
    if (warmUp_) {
      if (const auto* built = std::get_if<PreparedSurface>(&surface))
        warmUp_(request.scene, *built);
    }
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    const bool later = later_ && std::holds_alternative<PreparedSurface>(surface);
    const Scene built = later ? request.scene : Scene{};
    lock.lock();
    running_ = false;
    done_ = Result{{request.id, std::move(request.scene), std::move(surface)}, ms};
    lock.unlock();
    if (wake_) wake_();
    lock.lock();
    if (later &&
        !cv_.wait_for(lock, kLaterDelay, [this] { return stop_ || queued_.has_value(); })) {
      lock.unlock();
      later_(built);
      lock.lock();
    }
  }
}

}  // namespace zs::session
