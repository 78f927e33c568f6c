#include "interval/report.hpp"

#include <cstdio>
#include <sstream>

namespace zs {

std::string octreeReport(const Octree& tree) {
  std::ostringstream s;
  const char* criteria = tree.settings.criteria == Criteria::Thesis ? "thesis" : "uniform";
  char line[160];
  std::snprintf(line, sizeof line,
                "octree: level %d, criteria %s, domain [%g,%g]x[%g,%g]x[%g,%g], %u thread%s\n",
                tree.settings.level, criteria, tree.domain.min[0], tree.domain.max[0],
                tree.domain.min[1], tree.domain.max[1], tree.domain.min[2], tree.domain.max[2],
                tree.threads, tree.threads == 1 ? "" : "s");
  s << line;
  if (tree.ball) {
    std::snprintf(line, sizeof line, "clipped to the sphere of center (%g, %g, %g), radius %g\n",
                  tree.ball->center[0], tree.ball->center[1], tree.ball->center[2],
                  tree.ball->radius);
    s << line;
  }
  s << "level      tested        kept      leaves\n";
  for (std::size_t l = 0; l < tree.levels.size(); ++l) {
    const LevelStats& st = tree.levels[l];
    std::snprintf(line, sizeof line, "%5zu %11zu %11zu %11zu\n", l, st.tested, st.kept, st.leaves);
    s << line;
  }
  std::snprintf(line, sizeof line, "leaves: %zu   boxes tested: %zu   build time: %.3f ms\n",
                tree.leaves.size(), tree.testedCount(), tree.buildSeconds * 1e3);
  s << line;
  return s.str();
}

void writeLeafCsv(const Octree& tree, std::ostream& out) {
  out << "level,xmin,xmax,ymin,ymax,zmin,zmax\n";
  char line[200];
  for (const OctreeLeaf& leaf : tree.leaves) {
    const Box& b = leaf.box;
    std::snprintf(line, sizeof line, "%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", leaf.level,
                  b.min[0], b.max[0], b.min[1], b.max[1], b.min[2], b.max[2]);
    out << line;
  }
}

}  // namespace zs
