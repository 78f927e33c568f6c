# One INTERFACE target carries our warning flags; link it privately into each of our targets.
add_library(zs_warnings INTERFACE)
target_compile_options(zs_warnings INTERFACE
  $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wpedantic -Werror=switch -Werror=return-type>)
