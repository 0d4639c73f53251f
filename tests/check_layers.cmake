# cmake -DSRC_DIR=... -P check_layers.cmake: the layer rules of cmake/Layers.cmake on a tree
# (the project's src/, or tests/layering/'s broken fixture, which must fail).
include("${CMAKE_CURRENT_LIST_DIR}/../cmake/Layers.cmake")
cspacelab_check_layers("${SRC_DIR}")
message(STATUS "layers hold in ${SRC_DIR}")
