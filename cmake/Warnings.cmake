# One warning policy for every target of ours (not for third-party sources).
add_library(cspacelab_warnings INTERFACE)
target_compile_options(cspacelab_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion -Wdouble-promotion
  -Wnon-virtual-dtor -Wold-style-cast
  # A switch on a closed set (RobotKind, PrmPhase, event kinds) that misses a member is an
  # error, not a warning: adding a robot type must stop the build at every place that decides
  # by kind (issue 23: with warnings only, a new robot built, linked and gave wrong clearances).
  -Werror=switch)
# No -ffast-math anywhere: the roadmap must be bit-identical natively and in wasm.
