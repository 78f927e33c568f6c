#pragma once
// Text output of an octree for the `zeroset octree` command: takes a built Octree, puts out
// a human-readable summary (boxes per level, leaves, build time) and the --dump CSV
// (header `level,xmin,xmax,ymin,ymax,zmin,zmax`, then one line per kept leaf).
#include <ostream>
#include <string>

#include "interval/octree.hpp"

namespace zs {

std::string octreeReport(const Octree& tree);

// Coordinates are written with 17 significant digits, so they read back bit for bit.
void writeLeafCsv(const Octree& tree, std::ostream& out);

}  // namespace zs
