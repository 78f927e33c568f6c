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

// A first picture while typing: at least half the size each way, at most a quarter.
inline constexpr double kFirstPictureBudgetMs = 40;
inline constexpr int kFirstPictureMinScale = 2, kFirstPictureMaxScale = 4;

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
