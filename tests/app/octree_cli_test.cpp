// `zeroset octree` end to end: its statistics and the surface's bounds it reports (what the
// exact tracing methods clip rays to, docs/hierarchy.md).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "process.hpp"

namespace zs::test {
namespace {

namespace fs = std::filesystem;

int runZeroset(const std::vector<std::string>& args, std::string& output) {
  std::vector<std::string> argv{ZS_ZEROSET_EXE};
  argv.insert(argv.end(), args.begin(), args.end());
  const fs::path log = freshDir("octree_cli") / "log.txt";
  Child c(argv, {}, Stdio::File, log);
  const int status = c.wait(120);
  output = readText(log);
  return status;
}

TEST(OctreeCommand, ReportsTheSurfacesBounds) {
  std::string out;
  // A unit sphere in [-2, 2]^3: the level-6 cells (1/16 wide) touching it reach 1/16 past it.
  ASSERT_EQ(runZeroset({"octree", "x^2+y^2+z^2-1", "--domain", "-2,2,-2,2,-2,2"}, out), 0) << out;
  EXPECT_NE(out.find("leaves: 8"), std::string::npos) << out;
  EXPECT_NE(out.find("surface bounds: [-1.0625,1.0625]x[-1.0625,1.0625]x[-1.0625,1.0625]"),
            std::string::npos)
      << out;
}

TEST(OctreeCommand, SaysWhenNoCellCanHoldTheSurface) {
  std::string out;
  ASSERT_EQ(runZeroset({"octree", "x^2+y^2+z^2+1"}, out), 0) << out;
  EXPECT_NE(out.find("leaves: 0"), std::string::npos) << out;
  EXPECT_NE(out.find("surface bounds: empty"), std::string::npos) << out;
}

}  // namespace
}  // namespace zs::test
