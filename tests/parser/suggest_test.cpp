// The edit distance behind every "did you mean" hint: the plain distance, the same answer
// with a limit wherever the distance is within it, and the closest of several names.
#include "parser/suggest.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>

namespace zs {
namespace {

TEST(Suggest, EditDistanceCountsInsertionsDeletionsSubstitutionsAndSwaps) {
  EXPECT_EQ(editDistance("", ""), 0u);
  EXPECT_EQ(editDistance("sin", ""), 3u);
  EXPECT_EQ(editDistance("sin", "sinh"), 1u);
  EXPECT_EQ(editDistance("cos", "cosh"), 1u);
  EXPECT_EQ(editDistance("sqrt", "sqtr"), 1u);  // an adjacent swap
  EXPECT_EQ(editDistance("fov_y", "fovy"), 1u);
  EXPECT_EQ(editDistance("kitten", "sitting"), 3u);
}

TEST(Suggest, ALimitGivesTheSameDistanceWithinItAndLimitPlusOneBeyond) {
  std::mt19937 rng(7);
  auto word = [&] {
    std::string w(rng() % 12, 'a');
    for (char& c : w) c = static_cast<char>('a' + rng() % 4);  // few letters: near misses
    return w;
  };
  for (int i = 0; i < 2000; ++i) {
    const std::string a = word(), b = word();
    const std::size_t full = editDistance(a, b);
    for (std::size_t limit : {0u, 1u, 2u, 3u, 5u}) {
      const std::size_t bounded = editDistance(a, b, limit);
      EXPECT_EQ(bounded, full <= limit ? full : limit + 1) << a << " " << b << " " << limit;
    }
  }
}

TEST(Suggest, ClosestNameIsTheNearestWithinTheDistanceAndSkipsFarLengths) {
  const std::vector<std::string_view> names{"camera_height", "camera_fov", "scale"};
  EXPECT_EQ(closestName("camera_heigth", names, 3), "camera_height");
  EXPECT_EQ(closestName("scael", names, 3), "scale");
  EXPECT_FALSE(closestName(std::string(5000, 'q'), names, 3));
  EXPECT_FALSE(closestName("zzzzzzzz", names, 3));
}

}  // namespace
}  // namespace zs
