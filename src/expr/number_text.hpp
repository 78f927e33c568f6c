#pragma once
// Numbers to and from text, exactly: the shortest decimal that reads back to the same double
// (or float), as std::to_chars writes it, and a strict decimal reader, as std::from_chars
// reads. Where the standard library lacks the floating-point overloads (emscripten's libc++,
// the web build), an equivalent made of printf's %.*e and strtod is used; the native tests
// check that it writes exactly what std::to_chars writes.
#include <optional>
#include <string>
#include <string_view>

namespace zs {

// std::to_chars(double) / (float) text: "inf", "-inf", "nan" for those.
std::string shortestText(double v);
std::string shortestText(float v);

// The same by printf and strtod, whatever the library has (exposed for the tests).
std::string shortestTextPortable(double v);
std::string shortestTextPortable(float v);

// The whole of `text` as a decimal number in from_chars' general format (an optional '-',
// digits with an optional point, an optional exponent; "inf", "nan"); nothing otherwise.
std::optional<double> parseDecimal(std::string_view text);

}  // namespace zs
