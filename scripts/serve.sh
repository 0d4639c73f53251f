#!/usr/bin/env bash
# Builds the web app and serves it on http://127.0.0.1:8000/ (PORT=... to change the port).
# Installs whatever the web build is missing first (scripts/setup.sh --wasm). CORS='*' (or an
# origin) lets course pages of other origins use the script-tag embed (static-server.mjs --cors).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
source scripts/env.sh

bash scripts/setup.sh --wasm
echo "[serve] building the web app (build/wasm)"
cmake --preset wasm >/dev/null
cmake --build --preset wasm --target cspacelab_app cspacelab_web cspacelab_single_file
exec node scripts/static-server.mjs build/wasm/dist "${PORT:-8000}" 127.0.0.1 ${CORS:+--cors "$CORS"}
