# Header-only dependencies from Debian: Eigen, nlohmann-json, doctest.
#
# Emscripten's sysroot hides /usr/include, and adding -I/usr/include breaks its libc headers.
# So both builds see these libraries through folders of symlinks in the build tree that hold
# nothing but them. Two folders, so that the core cannot even see doctest.
set(_shim "${CMAKE_BINARY_DIR}/thirdparty-include")

function(_cspacelab_shim folder name target)
  if(NOT EXISTS "${target}")
    message(FATAL_ERROR "${target} not found: run scripts/setup.sh (Debian package providing '${name}')")
  endif()
  file(MAKE_DIRECTORY "${_shim}/${folder}")
  file(CREATE_LINK "${target}" "${_shim}/${folder}/${name}" SYMBOLIC)
endfunction()

_cspacelab_shim(core Eigen "/usr/include/eigen3/Eigen")
_cspacelab_shim(core nlohmann "/usr/include/nlohmann")
_cspacelab_shim(test doctest "/usr/include/doctest")

# What src/core may use, and nothing else.
add_library(cspacelab_core_deps INTERFACE)
target_include_directories(cspacelab_core_deps SYSTEM INTERFACE "${_shim}/core")
# Identical bits natively and in wasm: Eigen's SSE reductions sum in another order than its
# scalar code, so Eigen stays scalar everywhere (the core's hot loops are written by hand), and
# no compiler may fuse a*b+c into an FMA in one build and not in the other.
target_compile_definitions(cspacelab_core_deps INTERFACE EIGEN_DONT_VECTORIZE)
target_compile_options(cspacelab_core_deps INTERFACE -ffp-contract=off)
# Nothing here (the core, and the app, CLI and tests that link it) reads errno after a math
# function such as sqrt; without errno the compiler may vectorise loops of square roots (sqrt
# is exact either way: no bit changes). strtod and strtol still set it (the CLI reads that).
target_compile_options(cspacelab_core_deps INTERFACE -fno-math-errno)

add_library(cspacelab_doctest INTERFACE)
target_include_directories(cspacelab_doctest SYSTEM INTERFACE "${_shim}/test")
