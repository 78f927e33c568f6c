# One INTERFACE target carries our warning flags; link it privately into each of our targets.
add_library(zs_warnings INTERFACE)
target_compile_options(zs_warnings INTERFACE
  $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wpedantic -Werror=switch -Werror=return-type>
  # GCC 12 reports impossible memcpy overlaps inside std::string concatenation (GCC PR 105329).
  $<$<CXX_COMPILER_ID:GNU>:-Wno-restrict>)
