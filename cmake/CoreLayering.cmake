# src/core is a pure library: Eigen and nlohmann-json only. Its target gets no other include
# path (see src/core/CMakeLists.txt); this scan also refuses, at configure time, any source that
# names a UI or platform header, so a slip fails loudly instead of compiling by accident.
include("${CMAKE_CURRENT_LIST_DIR}/Layers.cmake")
function(cspacelab_check_core_layering dir)
  cspacelab_check_layers("${dir}/..")
  file(GLOB_RECURSE _files "${dir}/*.hpp" "${dir}/*.cpp")
  foreach(_f IN LISTS _files)
    file(STRINGS "${_f}" _bad REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"](SDL|imgui|emscripten|GL/|GLES|backends/)")
    if(_bad)
      message(FATAL_ERROR "src/core must not include UI/platform headers: ${_f}: ${_bad}")
    endif()
  endforeach()
endfunction()
