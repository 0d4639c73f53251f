# Shared environment for the project's scripts (sourced, not run).
# Paths of the build tree and the settings Debian's Emscripten 3.1.6 needs on this machine.

CSL_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
CSL_BUILD="$CSL_ROOT/build"
CSL_DEPS="$CSL_BUILD/deps"                 # source packages and SDL2-for-wasm, kept between builds
CSL_SDL2_WASM="$CSL_DEPS/sdl2-wasm"

# The machine's node is not Debian's, so emcc's own modules (acorn) are not on its path.
export NODE_PATH="/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}"
