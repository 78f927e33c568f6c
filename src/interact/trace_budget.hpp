#pragma once
// How much to reduce a picture's resolution to keep a trace within a time budget: takes the
// cost per pixel measured on the last trace and the full size, puts out the divisor of each
// side. The viewer's drags (33 ms, 30 fps) and first pictures while typing (40 ms) use it,
// and `zeroset bench --typing` uses the same rule to report what the viewer shows.
#include <algorithm>

namespace zs::interact {

// The smallest divisor in [lo, hi] whose estimated trace (msPerPixel times the pixels left)
// fits `budgetMs`, or hi; lo when nothing was measured yet (msPerPixel <= 0).
inline int scaleForBudget(double msPerPixel, int width, int height, double budgetMs, int lo,
                          int hi) {
  if (msPerPixel <= 0) return lo;
  for (int s = lo; s < hi; ++s) {
    if (msPerPixel * double(std::max(1, width / s)) * double(std::max(1, height / s)) <= budgetMs)
      return s;
  }
  return hi;
}

// A first picture while typing: at least half the size each way, at most an eighth.
inline constexpr double kFirstPictureBudgetMs = 40;
inline constexpr int kFirstPictureMinScale = 2, kFirstPictureMaxScale = 8;

// What a first picture (the tape interpreter's) costs, learnt from the ones before it, for
// the size of the next. The last picture's cost per pixel alone misjudges the keystroke that
// changes most: the one that makes a surface appear where the last formula drew nothing, or
// that adds a term. So the estimate is also the tape's length times the most a picture has
// cost per pixel and tape instruction (through the same dispatch: the polynomial one or the
// one with every operation), which fades by kForget with each later picture so that one
// costly formula does not keep every later picture small. That estimate is not stretched
// far: a tape more than kStretch times as long as the longest measured (through the same
// dispatch) is drawn at the smallest size: what a longer formula adds is often what makes
// each of its instructions costlier per pixel too (a surface with more sheets, more rays
// with roots to isolate), which no picture of the shorter tape can show.
class FirstPictureCost {
 public:
  static constexpr double kForget = 0.75;
  static constexpr double kStretch = 1.5;

  // The divisor of each side for a width x height picture of a tape of `instructions` steps.
  int scale(int width, int height, int instructions, bool polynomial) const {
    if (double(instructions) > kStretch * double(longest_[polynomial]))
      return kFirstPictureMaxScale;
    const double perPixel =
        std::max(lastPerPixel_, perInstruction_[polynomial] * double(std::max(1, instructions)));
    return scaleForBudget(perPixel, width, height, kFirstPictureBudgetMs, kFirstPictureMinScale,
                          kFirstPictureMaxScale);
  }
  // A first picture of `pixels` pixels took `ms`.
  void measured(double ms, double pixels, int instructions, bool polynomial) {
    if (!(ms > 0) || !(pixels > 0)) return;
    lastPerPixel_ = ms / pixels;
    double& most = perInstruction_[polynomial];
    most = std::max(lastPerPixel_ / double(std::max(1, instructions)), kForget * most);
    longest_[polynomial] = std::max(longest_[polynomial], instructions);
  }

 private:
  double lastPerPixel_ = 0;
  double perInstruction_[2] = {0, 0};  // [polynomial]: ms per pixel and tape instruction
  int longest_[2] = {0, 0};            // [polynomial]: the longest tape measured
};

// A picture while a drag, a wheel or a slider moves it: 30 frames a second, down to a
// quarter of the size each way.
inline constexpr double kDragBudgetMs = 33;
inline constexpr int kDragMinScale = 1, kDragMaxScale = 4;
// Before any picture has been timed, a drag is drawn at half size.
inline constexpr int kDragUnmeasuredScale = 2;

// The divisor for a picture while dragging, from the last picture's cost per pixel.
inline int dragScale(double msPerPixel, int width, int height) {
  if (msPerPixel <= 0) return kDragUnmeasuredScale;
  return scaleForBudget(msPerPixel, width, height, kDragBudgetMs, kDragMinScale, kDragMaxScale);
}

}  // namespace zs::interact
