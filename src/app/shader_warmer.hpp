#pragma once
// The surface worker's second job (surface_worker.hpp, its warm-up step): in a headless GL
// context of its own, compile each new surface's program and draw it once, from the scene's
// eye at a quarter of its size, into a target of the formats the front end draws to (the
// viewer's window: render/view_target.hpp; `bench --typing`: the tracer's offscreen
// target), so the driver's shader cache holds the very program the front end asks for
// next, and its compile of it takes milliseconds instead of stopping the picture. When the
// formula box first gets the focus it warms the tape interpreters (pipeline/load_surface.hpp)
// the same way, on a thread and context of their own (seconds of JIT on llvmpipe that no
// build waits for, paid only by a session that edits a formula); the window then draws every
// new formula's first picture with them. Without a headless context (no EGL) it does nothing
// and the window compiles as before.
#include <array>
#include <atomic>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "pipeline/load_surface.hpp"
#include "render/gl_context.hpp"
#include "render/view_target.hpp"

namespace zs::app {

class ShaderWarmer {
 public:
  // What the front end draws into: a ViewTarget (the viewer) or RayTracer's own offscreen
  // target (drawOffscreen, render).
  enum class Target { Window, Offscreen };
  explicit ShaderWarmer(Target target = Target::Window, Backend backend = Backend::Egl)
      : kind_(target), backend_(backend) {}
  ~ShaderWarmer();  // waits for the interpreters' thread
  ShaderWarmer(const ShaderWarmer&) = delete;
  ShaderWarmer& operator=(const ShaderWarmer&) = delete;

  // On the surface worker's thread: a new surface's program (the frame's own, without the
  // beam pass and tile mask where they are new); the release of every GL object and the
  // context as the worker ends.
  void warm(const Scene& scene, const PreparedSurface& surface);
  void stop();
  // On the surface worker's thread, later (SurfaceWorker::Later): the passes the last warm
  // left out, drawn at the scene's full size.
  void warmPasses(const Scene& scene);
  // A program as passesWarm knows it: the hash of its fragment shader's text.
  static std::size_t programKey(const std::string& fragmentShader);
  // Whether the front end may draw the program with its beam pass and tile mask (any
  // thread): false only from a warm that left them out to its warmPasses. Until then their
  // compile would stop the front end's picture, which is the same without them
  // (RayTracer::setBeamPass), only slower to draw.
  bool passesWarm(std::size_t program) const;

  // Whether the interpreters for this kind of method have been warmed (any thread).
  bool interpretersWarm(bool sampling) const { return interpretersWarm_[sampling].load(); }
  // The user is about to type a formula (the box got the focus): the interpreters for
  // `scene`'s method are warmed on their own thread, once.
  void wantInterpreters(const Scene& scene);

 private:
  static constexpr std::size_t kRemembered = 16;  // programs whose passes are warm

  bool ensureContext();
  void draw(const Scene& scene, int width, int height);
  static bool contains(const std::vector<std::size_t>& programs, std::size_t program);
  static void remember(std::vector<std::size_t>& programs, std::size_t program);

  Target kind_;
  Backend backend_;
  std::unique_ptr<GlContext> context_;
  bool failed_ = false;
  std::unique_ptr<RayTracer> tracer_;
  std::unique_ptr<ViewTarget> target_;
  std::thread interpretersThread_;
  std::array<std::atomic<bool>, 2> interpretersWarm_{};
  // Programs by programKey: the one loaded last (0: none), those whose passes wait for
  // warmPasses, and those whose passes are warm (the last kRemembered of each).
  std::size_t loaded_ = 0;
  mutable std::mutex mutex_;
  std::vector<std::size_t> deferred_, warm_;
};

// The window's variant of a picture in a ViewTarget of width x height pixels: what the
// warmer and the window's own first use draw. llvmpipe compiles a program again for each
// state it is drawn in, and whether a frame skips its clear tiles with a stencil test
// depends on the picture (render/beam_pass.hpp), so warm-ups draw pictures like the ones
// that follow: a formula's own program at a quarter of the scene's size from its eye, the
// interpreters at a first picture's size.
void drawWarmUp(RayTracer& tracer, ViewTarget& target, const Scene& scene, int width, int height);
// An interpreter's warm-up (TapeInterpreters' Draw) for the first pictures of a window of
// windowWidth x windowHeight: drawWarmUp at the largest size a first picture takes there.
void drawInterpreterWarmUp(RayTracer& tracer, ViewTarget& target, const Scene& scene,
                           int windowWidth, int windowHeight);

}  // namespace zs::app
