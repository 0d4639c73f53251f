#!/usr/bin/env bash
# Installs what C-Space Lab needs on Debian 12, and only what is missing.
#
#   scripts/setup.sh            everything (native, wasm, browser tests)
#   scripts/setup.sh --wasm     only what building and serving the web app needs
#
# Sources: Debian's archive (binary and source packages) and the npm registry,
# nothing else. Every step is idempotent: a second run does nothing and says so.
# Any failure names the package or step and exits non-zero.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# shellcheck source=scripts/env.sh
source "$ROOT/scripts/env.sh"

mode=all
case "${1:-}" in
  --wasm) mode=wasm ;;
  "") ;;
  *) echo "usage: scripts/setup.sh [--wasm]" >&2; exit 2 ;;
esac

step() { printf '\033[1m[setup]\033[0m %s\n' "$*"; }
fail() { printf '[setup] FAILED: %s\n' "$*" >&2; exit 1; }

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || fail "not root and no sudo: cannot install Debian packages"
  SUDO="sudo"
fi

# ---------------------------------------------------------------- Debian packages
wasm_pkgs=(cmake ninja-build g++ python3 dpkg-dev emscripten libeigen3-dev nlohmann-json3-dev
           doctest-dev fonts-dejavu-core fonttools)
native_pkgs=(libsdl2-dev libgl-dev chromium xvfb libompl-dev clang libclang-rt-14-dev zlib1g-dev)
pkgs=("${wasm_pkgs[@]}")
[ "$mode" = all ] && pkgs+=("${native_pkgs[@]}")
command -v node >/dev/null || pkgs+=(nodejs)
command -v npm >/dev/null || [ "$mode" = wasm ] || pkgs+=(npm)

missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
apt_updated=0
if [ ${#missing[@]} -gt 0 ]; then
  step "installing Debian packages: ${missing[*]}"
  $SUDO apt-get update -qq || fail "apt-get update"
  apt_updated=1
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" \
    || fail "apt-get install ${missing[*]}"
else
  step "Debian packages: all present"
fi

# ---------------------------------------------------------------- source packages
# SDL2 and Dear ImGui sources for the wasm build come from Debian's source packages.
# apt only offers them with a deb-src entry, which we derive from the machine's own
# deb entry for the main archive (no host name is written in this project).
fetch_source() { # name  dir-glob
  local name=$1 glob=$2
  if compgen -G "$CSL_DEPS/src/$glob" >/dev/null; then return 0; fi
  step "fetching Debian source package '$name'"
  local list=/etc/apt/sources.list.d/cspacelab-deb-src.sources
  if ! grep -rqs '^Types:.*deb-src' /etc/apt/sources.list.d/ \
     && ! grep -qs '^deb-src' /etc/apt/sources.list /etc/apt/sources.list.d/*.list 2>/dev/null; then
    local src=/etc/apt/sources.list.d/debian.sources
    [ -f "$src" ] || fail "no $src to derive a deb-src entry from; add one for 'bookworm' by hand"
    # First stanza only (the main archive); Types -> deb-src, Suites -> bookworm.
    awk 'BEGIN{RS="";ORS="\n\n"} NR==1{print; exit}' "$src" \
      | sed -e 's/^Types:.*/Types: deb-src/' -e 's/^Suites:.*/Suites: bookworm/' \
      | $SUDO tee "$list" >/dev/null || fail "writing $list"
    apt_updated=0
  fi
  if [ "$apt_updated" = 0 ]; then
    $SUDO apt-get update -qq || fail "apt-get update (for source packages)"
    apt_updated=1
  fi
  mkdir -p "$CSL_DEPS/src"
  (cd "$CSL_DEPS/src" && apt-get source -qq --download-only "$name" >/dev/null) \
    || fail "apt-get source --download-only $name"
  # The upstream tarball is enough: Debian's patches only concern Debian's packaging.
  local orig
  orig=$(ls "$CSL_DEPS"/src/"${name}"_*.orig.tar.* | head -n1) || fail "no orig tarball for $name"
  tar -xf "$orig" -C "$CSL_DEPS/src" || fail "unpacking $orig"
  compgen -G "$CSL_DEPS/src/$glob" >/dev/null || fail "unpacked $name but found no $glob"
}
fetch_source imgui "imgui-1.*"
fetch_source libsdl2 "SDL2-2.*"

# ---------------------------------------------------------------- SDL2 for wasm
# -sUSE_SDL=2 would download a port at build time; we build Debian's SDL2 source
# with its own CMake once (about 3.5 min on 2 cores) and keep it in the build tree.
if [ ! -f "$CSL_SDL2_WASM/lib/libSDL2.a" ]; then
  step "building SDL2 for wasm (once, cached in $CSL_SDL2_WASM)"
  sdl_src=$(compgen -G "$CSL_DEPS/src/SDL2-2.*" | head -n1)
  rm -rf "$CSL_DEPS/sdl2-wasm-build"
  emcmake cmake -S "$sdl_src" -B "$CSL_DEPS/sdl2-wasm-build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_INSTALL_PREFIX="$CSL_SDL2_WASM" -DSDL_SHARED=OFF -DSDL_STATIC=ON -DSDL_TEST=OFF \
    -DSDL_AUDIO=OFF -DSDL_JOYSTICK=OFF -DSDL_HAPTIC=OFF -DSDL_SENSOR=OFF -DSDL_POWER=OFF \
    -DSDL_HIDAPI=OFF -DSDL_RENDER=OFF >"$CSL_DEPS/sdl2-wasm-configure.log" 2>&1 \
    || fail "configuring SDL2 for wasm (see $CSL_DEPS/sdl2-wasm-configure.log)"
  cmake --build "$CSL_DEPS/sdl2-wasm-build" --target install >"$CSL_DEPS/sdl2-wasm-build.log" 2>&1 \
    || fail "building SDL2 for wasm (see $CSL_DEPS/sdl2-wasm-build.log)"
  rm -rf "$CSL_DEPS/sdl2-wasm-build"
else
  step "SDL2 for wasm: cached"
fi

# ---------------------------------------------------------------- npm (browser tests)
if [ "$mode" = all ]; then
  # (axe-core: the accessibility test's checker, tests/e2e/accessibility.test.mjs; scorm-again:
  # the SCORM runtime of tests/web/assignment.test.mjs and tests/e2e/scorm.test.mjs)
  if [ ! -d "$ROOT/node_modules/playwright-core" ] || [ ! -d "$ROOT/node_modules/axe-core" ] \
     || [ ! -d "$ROOT/node_modules/scorm-again" ] || [ "$ROOT/package-lock.json" -nt "$ROOT/node_modules/.package-lock.json" ]; then
    step "installing npm packages from package-lock.json"
    (cd "$ROOT" && npm ci --no-audit --no-fund --loglevel=error) || fail "npm ci (playwright-core, axe-core, scorm-again)"
  else
    step "npm packages: present"
  fi
fi
step "done"
