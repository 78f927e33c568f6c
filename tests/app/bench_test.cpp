// `zeroset bench` without GL: the plan, the thesis' published numbers, the median, the
// reports (on made-up measurements, so no timing is ever asserted) and the plot rasterizer.
// The GL half runs as the ctest entry zeroset_bench_quick.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <tuple>

#include "app/bench/bench_report.hpp"
#include "app/bench/canvas.hpp"
#include "app/bench/fps_plot.hpp"
#include "app/bench/thesis_data.hpp"

namespace zs::bench {
namespace {

TEST(BenchPlan, FullPlanIsBothThesisGridsPlusDeeperLevelsOnceAndTheExactMethodBeside) {
  const std::vector<BenchConfig> plan = benchPlan(BenchOptions{});
  // Per surface, sampling: 9 cells of Table 5.2 + 9 of Table 5.3 - 3 shared + levels 3..6;
  // bernstein: levels 0..6.
  EXPECT_EQ(plan.size(), 7u * (9 + 9 - 3 + 4) + 7u * 7);
  std::set<std::tuple<int, int, int, double>> seen;
  std::set<std::pair<int, int>> exact;
  for (const BenchConfig& c : plan) {
    if (c.method == TracingMethod::Bernstein) {
      EXPECT_TRUE(exact.insert({c.surface, c.level}).second);
      continue;
    }
    EXPECT_EQ(c.method, TracingMethod::Sampling);  // the thesis' tables are its method's
    EXPECT_TRUE(seen.insert({c.surface, c.level, c.intervals, c.epsilon}).second);
  }
  for (int s = 1; s <= 7; ++s)
    for (int level = 0; level <= 6; ++level) {
      EXPECT_TRUE(seen.count({s, level, 10, 0.001})) << s << " " << level;
      EXPECT_TRUE(exact.count({s, level})) << s << " " << level;
    }
  EXPECT_TRUE(seen.count({5, 2, 20, 0.001}));
  EXPECT_TRUE(seen.count({5, 2, 10, 0.0001}));
  EXPECT_FALSE(seen.count({5, 3, 20, 0.001}));
}

TEST(BenchPlan, QuickPlanIsLevelsZeroToTwoAtTheRecommendedSettings) {
  const BenchOptions quick = quickOptions(BenchOptions{});
  EXPECT_EQ(quick.width, 160);
  EXPECT_LT(quick.frames, 20);
  const std::vector<BenchConfig> plan = benchPlan(quick);
  EXPECT_EQ(plan.size(), 7u * 3 * 2);  // both methods
  for (const BenchConfig& c : plan) {
    EXPECT_LE(c.level, 2);
    EXPECT_EQ(c.intervals, 10);
    EXPECT_EQ(c.epsilon, 0.001);
  }
}

TEST(BenchThesis, LooksUpEachTableByItsOwnColumns) {
  EXPECT_EQ(table52Fps(1, 0, 10, 0.001), 21);
  EXPECT_EQ(table53Fps(1, 0, 10, 0.001), 15);  // the shared cell differs between tables
  EXPECT_EQ(table52Fps(5, 2, 20, 0.001), 8);
  EXPECT_EQ(table53Fps(2, 1, 10, 0.0001), 18);
  EXPECT_FALSE(table52Fps(1, 0, 10, 0.01));
  EXPECT_FALSE(table53Fps(1, 0, 15, 0.001));
  EXPECT_FALSE(table52Fps(1, 3, 10, 0.001));
  EXPECT_FALSE(table52Fps(8, 0, 10, 0.001));
}

TEST(BenchStats, MedianAndEpsilonText) {
  EXPECT_EQ(median({}), 0);
  EXPECT_EQ(median({3, 1, 2}), 2);
  EXPECT_EQ(median({4, 1, 3, 2}), 2.5);
  EXPECT_EQ(formatEpsilon(0.01), "0.01");
  EXPECT_EQ(formatEpsilon(0.0001), "0.0001");
  EXPECT_EQ(formatEpsilon(1), "1");
}

BenchResults madeUp() {
  BenchResults r;
  r.options = quickOptions(BenchOptions{});
  r.device = "test device";
  r.shaderCache = "true";
  for (int level = 0; level <= 2; ++level) {
    ConfigResult c;
    c.config = {1, level, 10, 0.001};
    c.stats = {20, 4.0 * (level + 1), 3.0, 9.0};  // 250, 125, 83 fps
    c.leaves = std::size_t(1) << (3 * level);
    r.configs.push_back(c);
  }
  for (int level = 0; level <= 2; ++level) {
    ConfigResult c;
    c.config = {1, level, 10, 0.001, TracingMethod::Bernstein};
    c.stats = {20, 2.0, 1.5, 3.0};  // 500 fps
    r.configs.push_back(c);
  }
  FirstFrame f;
  f.surface = 1;
  f.firstDrawMs = 100;
  f.totalMs = 120;
  r.firstFrames.push_back(f);  // sampling
  f.method = TracingMethod::Bernstein;
  f.totalMs = 200;
  r.firstFrames.push_back(f);
  return r;
}

TEST(BenchReport, MarkdownPutsOursBesideTheThesisAndJudgesTheGoals) {
  const std::string md = markdownReport(madeUp());
  EXPECT_NE(md.find("| 1 | 0 | 250 | 21 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| | 2 | 83 | 20 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| 1 | 0 | - | 21 |"), std::string::npos);  // Table 5.3, 0.01: not run
  EXPECT_NE(md.find("3 of 3 - **met**"), std::string::npos) << md;
  // The first frame a user waits for is the default method's (200 ms here).
  EXPECT_NE(md.find("First frame <= 300 ms (issue 7): 1 of 1 surfaces - **met**; <= 150 ms "
                    "(goal): 0 of 1"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| 1 | sampling | 0.00 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| 92 |"), std::string::npos);  // JIT estimate: 100 - 8 ms (sampling)
  EXPECT_NE(md.find("| 98 |"), std::string::npos);  // 100 - 2 ms (bernstein)
  EXPECT_NE(md.find("Default method (bernstein), level 1, at >= 60 fps (issue 10): 1 of 1 - "
                    "**met**"),
            std::string::npos)
      << md;
  // Levels table: sampling 8 ms beside bernstein 2 ms at level 1.
  EXPECT_NE(md.find("| 8.00 | 125 | 2.00 | 500 | 4.00x |"), std::string::npos) << md;
}

TEST(BenchReport, InputReportPutsTheMethodsSideBySideAndExplainsAFallback) {
  InputBenchResults r;
  r.options = BenchOptions{};
  r.device = "test device";
  r.shaderCache = "true";
  r.scene.formula = "x^4 + y^4 + z^4 - 1";
  MethodResult sampling;
  sampling.stats = {20, 60.0, 58.0, 70.0};
  sampling.first.totalMs = 250;
  sampling.first.firstDrawMs = 220;
  sampling.leaves = 8;
  MethodResult exact = sampling;
  exact.method = TracingMethod::Bernstein;
  exact.stats = {20, 15.0, 14.0, 16.0};
  r.methods = {sampling, exact};
  std::string md = inputMarkdownReport(r);
  EXPECT_NE(md.find("# zeroset bench: x^4 + y^4 + z^4 - 1"), std::string::npos) << md;
  EXPECT_NE(md.find("| sampling | 60.00 | 16.7 | 58.00 | 70.00 | 250 | 220 | 8 |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| bernstein | 15.00 | 66.7 |"), std::string::npos) << md;
  EXPECT_NE(md.find("bernstein is 4.00x the speed of sampling"), std::string::npos) << md;

  r.methods[1].skipped = "warning: not a polynomial";
  md = inputMarkdownReport(r);
  EXPECT_NE(md.find("| bernstein | not used: see below |"), std::string::npos) << md;
  EXPECT_NE(md.find("warning: not a polynomial"), std::string::npos);
  EXPECT_EQ(md.find("the speed of sampling"), std::string::npos);
}

TEST(BenchReport, CsvHasOneRowPerConfigurationWithBothThesisColumns) {
  const std::string csv = configCsv(madeUp());
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 7);
  EXPECT_NE(
      csv.find("1,sampling,0,10,0.001,160,120,20,4.000,3.000,9.000,250.00,0.000,1,0,21,15,\n"),
      std::string::npos)
      << csv;
  // The thesis' numbers belong to its method only.
  EXPECT_NE(csv.find("1,bernstein,0,10,0.001,160,120,20,2.000,1.500,3.000,500.00,0.000,0,0,,,\n"),
            std::string::npos)
      << csv;
}

TEST(BenchCanvas, LinesTextAndMissingGlyphs) {
  Canvas canvas(20, 12, {255, 255, 255});
  canvas.line(0, 0, 9, 9, {0, 0, 0});
  for (int i = 0; i <= 9; ++i) EXPECT_EQ(canvas.image().pixel(i, i)[0], 0);
  EXPECT_EQ(canvas.image().pixel(9, 0)[0], 255);
  canvas.text(12, 0, "#", {10, 20, 30}, 1);  // no glyph: a hollow box, never nothing
  EXPECT_EQ(canvas.image().pixel(12, 0)[2], 30);
  EXPECT_EQ(canvas.image().pixel(13, 2)[2], 255);
  EXPECT_EQ(Canvas::textWidth("12", 2), 14);
}

TEST(BenchPlot, DrawsEachMeasuredSurfaceInItsColor) {
  const Image plot = fpsByLevelPlot(madeUp(), 400, 300);
  ASSERT_EQ(plot.width, 400);
  ASSERT_EQ(plot.height, 300);
  int surfaceOne = 0;
  for (int y = 0; y < plot.height; ++y)
    for (int x = 0; x < plot.width; ++x) {
      const std::uint8_t* p = plot.pixel(x, y);
      surfaceOne += p[0] == 31 && p[1] == 119 && p[2] == 180;
    }
  EXPECT_GT(surfaceOne, 100);  // its line, markers and legend bar
}

}  // namespace
}  // namespace zs::bench
