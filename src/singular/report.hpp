#pragma once
// Reports of the singular-point search: takes a SingularResult, puts out a table for people
// (one line per certified point, the regions left uncertified, the counts), CSV and JSON.
#include <cstddef>
#include <string>
#include <vector>

#include "singular/singular.hpp"

namespace zs {

// Uncertified boxes merged where they touch: a singular curve becomes one region.
struct UncertifiedRegion {
  Box box;                // bounding box of the merged boxes
  std::size_t boxes = 0;  // how many were merged
};
std::vector<UncertifiedRegion> uncertifiedRegions(const SingularResult& result);

std::string singularTable(const SingularResult& result);
std::string singularCsv(const SingularResult& result);
std::string singularJson(const SingularResult& result);

}  // namespace zs
