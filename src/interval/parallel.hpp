#pragma once
// The one thread pool: takes a count of independent tasks, a thread count and the work,
// runs work(task, worker) for every task and returns when all are done. It lives in the
// interval stage because that is the lowest stage with a user (the octree) and the one
// that links the threads library; the mesher reaches it through its link to interval.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <vector>
#ifndef __EMSCRIPTEN__
#include <thread>
#endif

namespace zs {

// How many workers parallelFor uses for `tasks` tasks when asked for `threads`: at least
// one, never more than there are tasks. Callers size per-worker state with it.
inline std::size_t workerCount(std::size_t tasks, std::size_t threads) {
  return std::clamp<std::size_t>(threads, 1, std::max<std::size_t>(tasks, 1));
}

// Calls work(task, worker) once for each task in [0, tasks), with worker in
// [0, workerCount(tasks, threads)); the calling thread is worker 0. Workers take the next
// task from a shared counter, so which worker runs a task, and when, depends on timing: a
// caller that wants results independent of the thread count keeps them per task and joins
// them in task order, and keeps per-worker state (an evaluator, statistics) per worker.
// One worker runs inline, and so does everything in the web build: it has no threads (no
// SharedArrayBuffer without COOP/COEP) and its libc++ lacks std::jthread.
template <class Work>
void parallelFor(std::size_t tasks, std::size_t threads, Work&& work) {
#ifdef __EMSCRIPTEN__
  (void)threads;
  for (std::size_t task = 0; task < tasks; ++task) work(task, std::size_t(0));
#else
  const std::size_t workers = workerCount(tasks, threads);
  if (workers == 1) {
    for (std::size_t task = 0; task < tasks; ++task) work(task, std::size_t(0));
    return;
  }
  std::atomic<std::size_t> next{0};
  auto drain = [&](std::size_t worker) {
    for (std::size_t task; (task = next.fetch_add(1)) < tasks;) work(task, worker);
  };
  std::vector<std::jthread> pool;  // joined on the way out, also when worker 0 throws
  pool.reserve(workers - 1);
  for (std::size_t worker = 1; worker < workers; ++worker) pool.emplace_back(drain, worker);
  drain(0);
#endif
}

}  // namespace zs
