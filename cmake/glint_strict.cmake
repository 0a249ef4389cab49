# Flags for glint's own tests, benches and examples (not imposed on users of the library).
# -ffp-contract=off: GCC would otherwise fuse a*b+c into an fma, which llvmpipe does not do;
# the parity tests compare the two paths operation by operation.
add_library(glint_strict INTERFACE)
target_compile_options(glint_strict INTERFACE
  -ffp-contract=off
  -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wsign-conversion -Wdouble-promotion
  -Wold-style-cast -Wnon-virtual-dtor -Werror)

option(GLINT_SANITIZE "Build tests with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
if(GLINT_SANITIZE)
  target_compile_options(glint_strict INTERFACE
    -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  target_link_options(glint_strict INTERFACE -fsanitize=address,undefined)
endif()
