# Dear ImGui 1.86 from Debian's source package (fetched by scripts/setup.sh), with the SDL2 and
# OpenGL3 backends, built the same way natively and for wasm. In 1.86 the SDL2 backend is
# imgui_impl_sdl.cpp (no "2").
file(GLOB _imgui_dir LIST_DIRECTORIES true "${CSPACELAB_DEPS_DIR}/src/imgui-1.*")
if(NOT _imgui_dir OR NOT EXISTS "${_imgui_dir}/imgui.cpp")
  message(FATAL_ERROR "Dear ImGui sources not found under ${CSPACELAB_DEPS_DIR}/src: run scripts/setup.sh")
endif()

add_library(cspacelab_imgui STATIC
  "${_imgui_dir}/imgui.cpp" "${_imgui_dir}/imgui_draw.cpp" "${_imgui_dir}/imgui_tables.cpp"
  "${_imgui_dir}/imgui_widgets.cpp"
  "${_imgui_dir}/backends/imgui_impl_sdl.cpp" "${_imgui_dir}/backends/imgui_impl_opengl3.cpp")
target_include_directories(cspacelab_imgui SYSTEM PUBLIC "${_imgui_dir}" "${_imgui_dir}/backends")
# 32-bit indices: a 5000-node roadmap is well over 65536 vertices, and one mesh is simpler to
# cache than several (WebGL2 and desktop GL both draw with 32-bit indices).
target_compile_definitions(cspacelab_imgui PUBLIC IMGUI_DISABLE_OBSOLETE_FUNCTIONS "ImDrawIdx=unsigned int")

if(EMSCRIPTEN)
  # SDL2 built from Debian's source with its own CMake by scripts/setup.sh (-sUSE_SDL=2 would
  # download a port at build time).
  set(_sdl "${CSPACELAB_DEPS_DIR}/sdl2-wasm")
  if(NOT EXISTS "${_sdl}/lib/libSDL2.a")
    message(FATAL_ERROR "${_sdl}/lib/libSDL2.a not found: run scripts/setup.sh")
  endif()
  target_include_directories(cspacelab_imgui SYSTEM PUBLIC "${_sdl}/include/SDL2")
  target_link_libraries(cspacelab_imgui PUBLIC "${_sdl}/lib/libSDL2.a")
  target_compile_definitions(cspacelab_imgui PUBLIC IMGUI_IMPL_OPENGL_ES3)
else()
  find_package(SDL2 REQUIRED CONFIG)
  find_package(OpenGL REQUIRED)
  target_link_libraries(cspacelab_imgui PUBLIC SDL2::SDL2 OpenGL::GL ${CMAKE_DL_LIBS})
endif()
