# One warning policy for every target of ours (not for third-party sources).
add_library(cspacelab_warnings INTERFACE)
target_compile_options(cspacelab_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion -Wdouble-promotion
  -Wnon-virtual-dtor -Wold-style-cast)
# No -ffast-math anywhere: the roadmap must be bit-identical natively and in wasm.
