# The UI font: DejaVu Sans from Debian's fonts-dejavu-core, cut at build time to the glyphs the
# lab shows (Latin, Greek letters, arrows, maths, geometric shapes, the homework map's check
# mark) with pyftsubset, and compiled into the program as a byte array. 757 KB -> about 80 KB
# of wasm; nothing of it is committed.
#
# The one list of Unicode ranges below feeds both pyftsubset and ImGui's glyph ranges.
set(CSPACELAB_FONT_RANGES
  0020-007E 00A0-00FF 0370-03FF 2010-205E 2070-209F 2190-21FF 2200-22FF 2308-230B 25A0-25FF
  2713-2713)
set(CSPACELAB_FONT_SOURCE "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf" CACHE FILEPATH "UI font")

function(cspacelab_embed_font out_var)
  find_program(PYFTSUBSET pyftsubset)
  if(NOT PYFTSUBSET)
    message(FATAL_ERROR "pyftsubset not found: run scripts/setup.sh (Debian package 'fonttools')")
  endif()
  if(NOT EXISTS "${CSPACELAB_FONT_SOURCE}")
    message(FATAL_ERROR "${CSPACELAB_FONT_SOURCE} not found: run scripts/setup.sh (fonts-dejavu-core)")
  endif()
  list(TRANSFORM CSPACELAB_FONT_RANGES PREPEND "U+" OUTPUT_VARIABLE _u)
  list(JOIN _u "," _unicodes)
  set(_ttf "${CMAKE_CURRENT_BINARY_DIR}/generated/ui-font.ttf")
  set(_cpp "${CMAKE_CURRENT_BINARY_DIR}/generated/ui_font_data.cpp")
  add_custom_command(OUTPUT "${_ttf}"
    COMMAND "${PYFTSUBSET}" "${CSPACELAB_FONT_SOURCE}" "--unicodes=${_unicodes}"
            "--output-file=${_ttf}" --layout-features= --no-hinting
    DEPENDS "${CSPACELAB_FONT_SOURCE}"
    COMMENT "Subsetting the UI font" VERBATIM)
  add_custom_command(OUTPUT "${_cpp}"
    COMMAND "${CMAKE_COMMAND}" "-DINPUT=${_ttf}" "-DOUTPUT=${_cpp}" "-DRANGES=${CSPACELAB_FONT_RANGES}"
            -P "${CMAKE_SOURCE_DIR}/cmake/EmbedFontScript.cmake"
    DEPENDS "${_ttf}" "${CMAKE_SOURCE_DIR}/cmake/EmbedFontScript.cmake"
    COMMENT "Embedding the UI font" VERBATIM)
  set(${out_var} "${_cpp}" PARENT_SCOPE)
endfunction()
