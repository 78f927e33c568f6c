#pragma once
// Prints a node as formula text that parses back to the very same node (round trip), with
// the fewest parentheses the grammar allows and constants written exactly (17 digits).
#include <cstddef>
#include <optional>
#include <string>

#include "expr/graph.hpp"

namespace zs {

// Printing a DAG expands shared subexpressions; nothing is returned when the text would
// exceed maxChars, or nest deeper than the parser accepts (kMaxNesting: the simplifier can
// build product and sum chains that need more parentheses than any text it was parsed from).
std::optional<std::string> print(const Graph& g, NodeId root, std::size_t maxChars = 1 << 24);

}  // namespace zs
