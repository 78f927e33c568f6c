// One long-lived worker thread; prepareSurface itself fans the octree out over every core.
#include "app/surface_worker.hpp"

#include <chrono>

namespace zs::app {

SurfaceWorker::SurfaceWorker(std::function<void()> wake, WarmUp warmUp,
                             std::function<void()> stop, Later later)
    : wake_(std::move(wake)),
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

std::uint64_t SurfaceWorker::submit(const Scene& scene) {
  std::uint64_t id;
  {
    std::lock_guard lock(mutex_);
    id = nextId_++;
    queued_.emplace(id, scene);
    queuedAt_ = std::chrono::steady_clock::now();
  }
  cv_.notify_all();
  return id;
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

std::uint64_t SurfaceWorker::lastSubmitted() const {
  std::lock_guard lock(mutex_);
  return nextId_ - 1;
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
    auto [id, scene] = std::move(*queued_);
    queued_.reset();
    const auto start = queuedAt_;
    running_ = true;
    lock.unlock();
    auto surface = prepareSurface(scene);
    if (warmUp_) {
      if (const auto* built = std::get_if<PreparedSurface>(&surface)) warmUp_(scene, *built);
    }
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    const bool later = later_ && std::holds_alternative<PreparedSurface>(surface);
    const Scene built = later ? scene : Scene{};
    lock.lock();
    running_ = false;
    done_ = Result{id, std::move(scene), std::move(surface), ms};
    lock.unlock();
    if (wake_) wake_();
    lock.lock();
    if (later && !cv_.wait_for(lock, kLaterDelay, [this] { return stop_ || queued_.has_value(); })) {
      lock.unlock();
      later_(built);
      lock.lock();
    }
  }
}

}  // namespace zs::app
