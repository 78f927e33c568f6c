#pragma once
// Names that parse but almost surely are typos (xy, x2, sinx, sinn(...)) and what to say
// about them; plus the edit distance used for "did you mean" hints.
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace zs {

struct NameProblem {
  std::string message;
  std::string hint;
};

// `call`: the name is followed by '('. Nothing when the name is a fine parameter name.
std::optional<NameProblem> diagnoseName(std::string_view name, bool call);

// Levenshtein distance (insert, delete, substitute, adjacent swap); any distance above
// `limit` is reported as limit + 1, found without finishing the table.
std::size_t editDistance(std::string_view a, std::string_view b,
                         std::size_t limit = std::numeric_limits<std::size_t>::max() - 1);

// The candidate closest to `word` within maxDistance, or nothing.
std::optional<std::string> closestName(std::string_view word,
                                       const std::vector<std::string_view>& candidates,
                                       std::size_t maxDistance = 2);

}  // namespace zs
