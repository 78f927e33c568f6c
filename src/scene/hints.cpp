#include "scene/hints.hpp"

#include <algorithm>
#include <vector>

#include "parser/suggest.hpp"
#include "scene/schema.hpp"

namespace zs::scene_detail {

namespace {

std::string_view parentOf(std::string_view dotted) {
  const auto dot = dotted.rfind('.');
  return dot == std::string_view::npos ? std::string_view{} : dotted.substr(0, dot);
}

std::string_view leafOf(std::string_view dotted) {
  const auto dot = dotted.rfind('.');
  return dot == std::string_view::npos ? dotted : dotted.substr(dot + 1);
}

// Every name a file may spell: leaves, the tables that hold them, formula and params.
std::vector<std::string> allNames() {
  std::vector<std::string> names{std::string(kFormulaKey), std::string(kParamsKey)};
  for (const ListSpec& l : listSpecs()) {
    for (std::string_view p = l.name; !p.empty(); p = parentOf(p)) {
      if (std::find(names.begin(), names.end(), p) == names.end()) names.emplace_back(p);
    }
  }
  for (const KeySpec& k : keySpecs()) {
    for (std::string_view p = k.name; !p.empty(); p = parentOf(p)) {
      if (std::find(names.begin(), names.end(), p) == names.end()) names.emplace_back(p);
    }
  }
  return names;
}

// Typos shorter than this are too far from what the user meant to be worth suggesting.
bool closeEnough(int distance, std::string_view word) {
  return distance <= std::max<int>(2, static_cast<int>(word.size()) / 3);
}

std::string quoteList(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : ", ") + s;
  return out;
}

// The formula parser's distance, so a key typo and a function typo are judged alike.
int distance(std::string_view a, std::string_view b) {
  return static_cast<int>(zs::editDistance(a, b));
}

}  // namespace

std::string unknownKeyHint(std::string_view dottedName) {
  const std::string_view parent = parentOf(dottedName);
  const std::string_view leaf = leafOf(dottedName);
  std::string best;
  int bestScore = 1 << 30;
  for (const std::string& candidate : allNames()) {
    // A key typed in the right table with a typo, or the right word in the wrong table
    // (fov_y at the top level instead of in [camera]): score both, prefer the same table.
    const bool sameTable = parentOf(candidate) == parent;
    const int byLeaf = distance(leaf, leafOf(candidate)) + (sameTable ? 0 : 1);
    const int byFull = distance(dottedName, candidate);
    const int score = std::min(byLeaf, byFull);
    if (score < bestScore) {
      bestScore = score;
      best = candidate;
    }
  }
  if (!best.empty() && closeEnough(bestScore, leaf)) {
    const bool sameTable = parentOf(best) == parent;
    return "did you mean \"" + std::string(sameTable ? leafOf(best) : best) + "\"?";
  }
  std::vector<std::string> siblings;
  for (const std::string& candidate : allNames()) {
    if (parentOf(candidate) == parent) siblings.emplace_back(leafOf(candidate));
  }
  const std::string where =
      parent.empty() ? "at the top level" : "in [" + std::string(parent) + "]";
  return "valid keys " + where + ": " + quoteList(siblings);
}

std::string choiceHint(std::string_view word, std::span<const std::string_view> choices) {
  std::vector<std::string> all;
  std::string_view best;
  int bestDistance = 1 << 30;
  for (std::string_view c : choices) {
    all.emplace_back("\"" + std::string(c) + "\"");
    // An abbreviation ("persp", "ortho") is as clear a slip as a typo.
    const int d = !word.empty() && c.starts_with(word) ? 0 : distance(word, c);
    if (d < bestDistance) {
      bestDistance = d;
      best = c;
    }
  }
  std::string hint;
  if (closeEnough(bestDistance, word)) hint = "did you mean \"" + std::string(best) + "\"? ";
  return hint + "expected one of " + quoteList(all);
}

}  // namespace zs::scene_detail
