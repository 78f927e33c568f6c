#include "expr/number_text.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

namespace zs {
namespace {

// Shortest %.*e text that reads back to v, rewritten in to_chars' choice of form: fixed
// where it is no longer than scientific, exponents with at least two digits.
template <class T>
std::string portable(T v) {
  if (std::isnan(v)) return std::signbit(v) ? "-nan" : "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  if (v == 0) return std::signbit(v) ? "-0" : "0";
  const int maxDigits = std::numeric_limits<T>::max_digits10;
  const bool negative = std::signbit(v);
  const double magnitude = std::fabs(double(v));
  auto readsBack = [&](const std::string& digits, int exponent) {
    std::string text =
        digits.substr(0, 1) + "." + digits.substr(1) + "e" + std::to_string(exponent);
    const T back = sizeof(T) == sizeof(float) ? T(std::strtof(text.c_str(), nullptr))
                                              : T(std::strtod(text.c_str(), nullptr));
    return back == T(magnitude);
  };
  // The shortest digits that read back. printf gives the nearest p-digit decimal; at a power
  // of two the rounding interval below is half as wide as above, so the nearest can miss
  // where its neighbour above (or below) reads back: to_chars finds that one.
  char buf[64];
  std::string digits;
  int exponent = 0;
  for (int p = 1; p <= maxDigits; ++p) {
    std::snprintf(buf, sizeof buf, "%.*e", p - 1, magnitude);
    const std::string text = buf;
    const std::size_t e = text.find('e');
    exponent = std::atoi(text.c_str() + e + 1);
    digits.clear();
    for (std::size_t i = 0; i < e; ++i)
      if (text[i] != '.') digits += text[i];
    if (readsBack(digits, exponent) || p == maxDigits) break;
    const long long m = std::atoll(digits.c_str());
    bool found = false;
    for (const long long next : {m + 1, m - 1}) {
      std::string d = std::to_string(next);
      int x = exponent + int(d.size()) - p;  // 10^p - 1 + 1 gains a digit, 10^(p-1) - 1 loses one
      if (next <= 0) continue;
      if (readsBack(d, x)) {
        digits = d;
        exponent = x;
        found = true;
        break;
      }
    }
    if (found) break;
  }
  while (digits.size() > 1 && digits.back() == '0') digits.pop_back();
  const int n = int(digits.size());
  std::string scientific = digits.substr(0, 1);
  if (n > 1) scientific += "." + digits.substr(1);
  const int a = exponent < 0 ? -exponent : exponent;
  scientific +=
      std::string("e") + (exponent < 0 ? "-" : "+") + (a < 10 ? "0" : "") + std::to_string(a);
  std::string fixed;
  if (exponent >= 0) {
    // An integer longer than its shortest digits: to_chars writes its exact value.
    if (exponent + 1 >= n) {
      std::snprintf(buf, sizeof buf, "%.0f", std::fabs(double(v)));
      fixed = buf;
    } else
      fixed = digits.substr(0, std::size_t(exponent + 1)) + "." +
              digits.substr(std::size_t(exponent + 1));
  } else {
    fixed = "0." + std::string(std::size_t(-exponent - 1), '0') + digits;
  }
  return (negative ? "-" : "") + (fixed.size() <= scientific.size() ? fixed : scientific);
}

template <class T>
std::string shortest(T v) {
#if defined(__cpp_lib_to_chars) && __cpp_lib_to_chars >= 201611L
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, res.ptr);
#else
  return portable(v);
#endif
}

}  // namespace

std::string shortestText(double v) {
  return shortest(v);
}
std::string shortestText(float v) {
  return shortest(v);
}
std::string shortestTextPortable(double v) {
  return portable(v);
}
std::string shortestTextPortable(float v) {
  return portable(v);
}

std::optional<double> parseDecimal(std::string_view text) {
#if defined(__cpp_lib_to_chars) && __cpp_lib_to_chars >= 201611L
  double x = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), x);
  if (ec != std::errc{} || ptr != text.data() + text.size()) return std::nullopt;
  return x;
#else
  // strtod takes more than from_chars (leading blanks and '+', hexadecimal): only the
  // characters of the general format may pass.
  if (text.empty() || text.size() > 400) return std::nullopt;
  for (char c : text) {
    const bool ok = (c >= '0' && c <= '9') || c == '.' || c == 'e' || c == 'E' || c == '-' ||
                    c == '+' || c == 'i' || c == 'n' || c == 'f' || c == 'a' || c == 't' ||
                    c == 'y' || c == 'I' || c == 'N' || c == 'F' || c == 'A' || c == 'T' ||
                    c == 'Y';
    if (!ok) return std::nullopt;
  }
  if (text[0] == '+') return std::nullopt;
  const std::string copy(text);
  char* end = nullptr;
  errno = 0;
  const double x = std::strtod(copy.c_str(), &end);
  // Out of double's range either way is no number, as from_chars says.
  if (end != copy.c_str() + copy.size() || errno == ERANGE) return std::nullopt;
  return x;
#endif
}

}  // namespace zs
