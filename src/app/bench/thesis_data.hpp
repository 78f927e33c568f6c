#pragma once
// The published side of the benchmark: the 7 test surfaces of thesis Table 5.1 (Gallegos
// 2018) with the frames per second its prototype reached on an Intel HD Graphics 3000 in
// Tables 5.2 and 5.3, plus the Barth sextic, on which the peers (jsurf, ImpVis) are compared too.
// Takes nothing, puts out constant data; header-only so the microbenchmarks can use it without
// linking the app. The fps values are transcribed from the thesis text
// (shared/seed/thesis-gallegos-2018.txt, "Cuadro 5.2" and "Cuadro 5.3"); they are the
// reference column, never something zeroset computes.
#include <array>
#include <optional>
#include <string_view>

namespace zs::bench {

struct ThesisSurface {
  int number;                // thesis Table 5.1 numbering, 1..7
  std::string_view name;     // the thesis' Spanish name
  std::string_view formula;  // in zeroset's formula language
};

inline constexpr std::array<ThesisSurface, 7> kThesisSurfaces{{
    {1, "Canal en Cruz", "x^2 + z^2 - y"},
    {2, "Cubica de Cayley",
     "x^2*y + x^2*z + y^2*x + y^2*z + z^2*y + z^2*x - (2/5)*(x*y + x*z + y*z)"},
    {3, "Cuboide", "x^4 + y^4 + z^4 - 1"},
    {4, "Peninsula", "x^2 + y^3 + z^5 - 1"},
    {5, "Cuartica de Klein", "x^3*y + y^3*z + z^3*x"},
    {6, "Silla Cuartica", "x^4 - z^4 - y"},
    {7, "Superficie Racor", "x^2*y^2 + y^2*z^2 + z^2*x^2 - 1"},
}};

// Barth's sextic with phi = (1 + sqrt 5) / 2 written out, so the benchmark measures the
// formula, not constant folding of sqrt(5).
inline constexpr std::string_view kBarthSextic =
    "4*(2.618033988749895*x^2 - y^2)*(2.618033988749895*y^2 - z^2)*"
    "(2.618033988749895*z^2 - x^2) - 4.23606797749979*(x^2 + y^2 + z^2 - 1)^2";

// The grids the thesis varied: levels 0..2 in both tables; Table 5.2 varies the number of
// sign-sampling intervals at epsilon 0.001, Table 5.3 varies epsilon at 10 intervals.
inline constexpr std::array<int, 3> kThesisLevels{0, 1, 2};
inline constexpr std::array<int, 3> kTable52Intervals{10, 15, 20};
inline constexpr double kTable52Epsilon = 0.001;
inline constexpr std::array<double, 3> kTable53Epsilons{0.01, 0.001, 0.0001};
inline constexpr int kTable53Intervals = 10;

// [surface - 1][level][column]: columns are kTable52Intervals / kTable53Epsilons.
inline constexpr int kTable52Fps[7][3][3] = {
    {{21, 16, 14}, {22, 18, 13}, {20, 15, 13}},  // 1
    {{20, 15, 11}, {21, 16, 10}, {19, 14, 10}},  // 2
    {{27, 22, 20}, {28, 23, 20}, {25, 19, 16}},  // 3
    {{27, 19, 15}, {28, 20, 15}, {27, 19, 14}},  // 4
    {{17, 12, 11}, {18, 13, 10}, {14, 10, 8}},   // 5
    {{22, 17, 13}, {23, 18, 12}, {19, 14, 10}},  // 6
    {{24, 19, 17}, {25, 20, 18}, {20, 16, 12}},  // 7
};
inline constexpr int kTable53Fps[7][3][3] = {
    {{21, 15, 13}, {22, 16, 12}, {18, 14, 10}},  // 1
    {{20, 18, 16}, {21, 19, 18}, {19, 15, 13}},  // 2
    {{27, 24, 22}, {28, 25, 22}, {25, 22, 18}},  // 3
    {{27, 24, 23}, {28, 26, 24}, {27, 25, 22}},  // 4
    {{17, 16, 14}, {18, 16, 14}, {14, 13, 12}},  // 5
    {{22, 20, 18}, {23, 21, 19}, {19, 17, 16}},  // 6
    {{24, 21, 18}, {25, 22, 20}, {20, 18, 16}},  // 7
};

// The thesis' fps for a configuration, when one of its tables has it. Table 5.2 wins for
// (10 intervals, 0.001), the one cell both tables contain (they disagree there, e.g.
// surface 1 level 0: 21 vs 15 fps; the Markdown report shows each table's own value).
inline std::optional<int> table52Fps(int surface, int level, int intervals, double epsilon) {
  if (surface < 1 || surface > 7 || level < 0 || level > 2 || epsilon != kTable52Epsilon)
    return std::nullopt;
  for (int c = 0; c < 3; ++c)
    if (kTable52Intervals[c] == intervals) return kTable52Fps[surface - 1][level][c];
  return std::nullopt;
}
inline std::optional<int> table53Fps(int surface, int level, int intervals, double epsilon) {
  if (surface < 1 || surface > 7 || level < 0 || level > 2 || intervals != kTable53Intervals)
    return std::nullopt;
  for (int c = 0; c < 3; ++c)
    if (kTable53Epsilons[c] == epsilon) return kTable53Fps[surface - 1][level][c];
  return std::nullopt;
}

}  // namespace zs::bench
