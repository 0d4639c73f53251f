# Settings shared by every wasm target. Decided once for the whole build:
# - native wasm exceptions (-fwasm-exceptions): nlohmann-json and doctest throw;
# - memory grows on demand; tests run under node with the real file system.
add_compile_options(-fwasm-exceptions)
add_link_options(-fwasm-exceptions -sALLOW_MEMORY_GROWTH=1)

# Link options for a wasm program meant to run under node (tests, benchmarks).
function(cspacelab_node_program target)
  target_link_options(${target} PRIVATE -sENVIRONMENT=node -sNODERAWFS=1 -sEXIT_RUNTIME=1)
endfunction()
