#!/usr/bin/env bash
# Builds everything (native + wasm) and runs every test; the last lines are ctest's summary.
#   scripts/test.sh [extra ctest arguments, e.g. -L browser or -R unit]
# Installs whatever is missing first (scripts/setup.sh).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
source scripts/env.sh

bash scripts/setup.sh
echo "[test] configuring and building native (build/native)"
mkdir -p build
cmake --preset native >build/configure-native.log 2>&1 || { cat build/configure-native.log; exit 1; }
cmake --build --preset native
echo "[test] configuring and building wasm (build/wasm)"
cmake --preset wasm >build/configure-wasm.log 2>&1 || { cat build/configure-wasm.log; exit 1; }
cmake --build --preset wasm
echo "[test] configuring and building the hardening build (build/hardening: clang, ASan + UBSan, fuzzers)"
cmake --preset hardening >build/configure-hardening.log 2>&1 || { cat build/configure-hardening.log; exit 1; }
cmake --build --preset hardening
echo "[test] running every test"
exec ctest --preset all "$@"
