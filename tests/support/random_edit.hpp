#pragma once
// Random edits of a scene for the property tests of the session and its front ends
// (tests/session, tests/app): formulas that parse and ones that do not, `--set`
// assignments of every key of the .surf schema (scene/schema.hpp) and of the lists' entries
// with random valid and invalid values, and .surf texts. The values of keys that cost
// seconds at their largest (octree level, supersampling, volume steps) stay small.
#include <random>
#include <span>
#include <string>

#include "scene/scene.hpp"

namespace zs::test {

std::span<const char* const> goodFormulas();
std::span<const char* const> badFormulas();

// One `KEY=VALUE` assignment as --set and :set take it, for a scene now `scene`; one in
// four is invalid (out of range, of the wrong type, an unknown key, a formula that fails).
std::string randomAssignment(std::mt19937_64& rng, const Scene& scene);

// A .surf text: a good formula with a method, or (good = false) one the loader refuses.
std::string randomSurfText(std::mt19937_64& rng, bool good);

std::string number(double v);

}  // namespace zs::test
