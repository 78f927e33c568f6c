#pragma once
// std::bit_cast for every standard library zeroset is built with: emscripten's libc++ (the
// web build) lacks it, and GCC and Clang both have the builtin it is made of.
#include <type_traits>

namespace zs {

template <class To, class From>
constexpr To bitCast(const From& from) noexcept {
  static_assert(sizeof(To) == sizeof(From) && std::is_trivially_copyable_v<From> &&
                std::is_trivially_copyable_v<To>);
  return __builtin_bit_cast(To, from);
}

}  // namespace zs
