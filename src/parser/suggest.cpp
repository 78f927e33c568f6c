#include "parser/suggest.hpp"

#include <algorithm>

#include "expr/opcode.hpp"
#include "i18n/translate.hpp"

namespace zs {

std::size_t editDistance(std::string_view a, std::string_view b, std::size_t limit) {
  // Optimal string alignment distance, three rows at a time (a swap looks two rows back).
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::size_t> rows(3 * (m + 1));
  auto row = [&](std::size_t i) { return rows.data() + (i % 3) * (m + 1); };
  for (std::size_t j = 0; j <= m; ++j) row(0)[j] = j;
  std::size_t previousMin = 0;
  for (std::size_t i = 1; i <= n; ++i) {
    std::size_t* d = row(i);
    const std::size_t* up = row(i - 1);
    const std::size_t* up2 = row(i - 2);
    d[0] = i;
    std::size_t rowMin = d[0];
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[j] = std::min({up[j] + 1, d[j - 1] + 1, up[j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[j] = std::min(d[j], up2[j - 2] + 1);
      rowMin = std::min(rowMin, d[j]);
    }
    // Every later entry is at least the smaller of the last two rows' minima.
    if (std::min(rowMin, previousMin) > limit) return limit + 1;
    previousMin = rowMin;
  }
  return std::min(row(n)[m], limit + 1);
}

std::optional<std::string> closestName(std::string_view word,
                                       const std::vector<std::string_view>& candidates,
                                       std::size_t maxDistance) {
  std::optional<std::string> best;
  std::size_t bestDistance = maxDistance + 1;
  for (std::string_view c : candidates) {
    // The distance is at least the difference in length: a candidate that cannot come
    // closer than the best so far is skipped unmeasured (a long mistyped line costs nothing).
    const std::size_t gap =
        word.size() > c.size() ? word.size() - c.size() : c.size() - word.size();
    if (gap >= bestDistance) continue;
    const std::size_t dist = editDistance(word, c, bestDistance - 1);
    if (dist < bestDistance) {
      bestDistance = dist;
      best = std::string(c);
    }
  }
  return best;
}

namespace {

bool onlyCoordinates(std::string_view s) {
  return std::all_of(s.begin(), s.end(), [](char c) { return c == 'x' || c == 'y' || c == 'z'; });
}

std::string spelledProduct(std::string_view letters) {
  std::string out;
  for (char c : letters) {
    if (!out.empty()) out += '*';
    out += c;
  }
  return out;
}

std::vector<std::string_view> functionNames() {
  std::vector<std::string_view> names;
  for (const OpInfo& info : kOpTable) {
    if (info.kind == OpKind::Call) names.push_back(info.spelling);
  }
  return names;
}

}  // namespace

std::optional<NameProblem> diagnoseName(std::string_view name, bool call) {
  if (name.size() > 1 && onlyCoordinates(name)) {
    return NameProblem{i18n::format(i18n::tr("'%s' is not a name"), std::string(name).c_str()),
                       i18n::format(i18n::tr("write %s for a product of coordinates"),
                                    spelledProduct(name).c_str())};
  }
  if (name.size() > 1 && onlyCoordinates(name.substr(0, 1)) &&
      std::all_of(name.begin() + 1, name.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    const std::string v(name.substr(0, 1)), n(name.substr(1));
    return NameProblem{i18n::format(i18n::tr("'%s' is not a name"), std::string(name).c_str()),
                       i18n::format(i18n::tr("write %s for a power or %s for a product"),
                                    (v + "^" + n).c_str(), (v + "*" + n).c_str())};
  }
  for (std::string_view fn : functionNames()) {
    if (name.size() > fn.size() && name.substr(0, fn.size()) == fn &&
        onlyCoordinates(name.substr(fn.size()))) {
      const std::string arg = spelledProduct(name.substr(fn.size()));
      return NameProblem{
          i18n::format(i18n::tr("'%s' is not a name"), std::string(name).c_str()),
          i18n::format(i18n::tr("write %s"), (std::string(fn) + "(" + arg + ")").c_str())};
    }
  }
  if (call && name.size() >= 2) {
    if (auto best = closestName(name, functionNames())) {
      return NameProblem{i18n::format(i18n::tr("unknown function '%s' \u2014 did you mean %s?"),
                                      std::string(name).c_str(), best->c_str()),
                         i18n::tr("the functions are listed in docs/formula.md")};
    }
  }
  return std::nullopt;
}

}  // namespace zs
